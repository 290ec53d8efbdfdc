// libFuzzer target: the CSV reader and its number parsing must read a file or raise InputError.
// Seed it with examples/01_cantilever/*.csv.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "io/csv_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    bpm::CsvTable table = bpm::read_csv(bpm::fuzz::write_input(data, size, ".csv"), "fuzz");
    table.convert_rows([&](std::size_t, const bpm::CsvRow& row) {
      for (std::size_t c = 0; c < row.fields.size(); ++c) {
        try {
          table.number(row, c, "value");
        } catch (const bpm::InputError&) {
        }
        try {
          table.integer(row, c, "id");
        } catch (const bpm::InputError&) {
        }
      }
    });
  } catch (const bpm::InputError&) {
  }
  return 0;
}
