// libFuzzer target: the binary structure tables (io/structure_table.hpp) must read or raise
// InputError. The input is the table without its checksum: the target appends the right one, so
// the mutations reach the decoder instead of stopping at the checksum. Seeds:
// tests/fuzz/seeds/*.bpk-payload, a particles and a bonds table without their checksum.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "io/byte_codec.hpp"
#include "io/structure_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view payload(reinterpret_cast<const char*>(data), size);
  bpm::ByteWriter sum;
  sum.u64(bpm::fnv1a64(payload));
  const std::string bytes = std::string(payload) + sum.bytes();
  const std::string path =
      bpm::fuzz::write_input(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), ".bpk");
  try {
    bpm::read_particle_table(path);
  } catch (const bpm::InputError&) {
  }
  try {
    bpm::read_bond_table(path);
  } catch (const bpm::InputError&) {
  }
  return 0;
}
