// libFuzzer target: a scenario file must load or raise InputError; anything else (another
// exception, a crash, a sanitizer report, a timeout) is a finding. Seed it with examples/*/*.yaml.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "scenario/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    bpm::load_scenario(bpm::fuzz::write_input(data, size, ".yaml"));
  } catch (const bpm::InputError&) {
  }
  return 0;
}
