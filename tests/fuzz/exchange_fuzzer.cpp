// libFuzzer target: other codes' structure files (`bpmkit convert`), a MUSEN text file
// (io/musen_text.hpp) and a LAMMPS data file (io/lammps_data.hpp), must read or raise InputError.
// Seeds: tests/fuzz/seeds/case1.musen.txt and case1.lammps-data, Chen's case 1 as `bpmkit convert`
// writes it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "io/lammps_data.hpp"
#include "io/musen_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = bpm::fuzz::write_input(data, size, ".txt");
  try {
    bpm::read_musen_structure(path);
  } catch (const bpm::InputError&) {
  }
  try {
    bpm::read_lammps_data(path);
  } catch (const bpm::InputError&) {
  }
  return 0;
}
