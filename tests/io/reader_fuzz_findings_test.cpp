// What the reader fuzzers (reader_fuzz_test.cpp, tests/fuzz/) found, each as the input that showed
// it; every one used to crash or run for minutes or for ever and is now an InputError naming the
// line and the fix, or reads.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <string>

#include "core/error.hpp"
#include "io/lammps_data.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::expect_contains;
using test::TempDir;

// yaml-cpp 0.7's LoadAll loops for ever, allocating, on a ',' outside brackets
// (jbeder/yaml-cpp#1040): a comment line broken in two left ", TBBM bonds ..." on a line of its
// own.
TEST(ReaderFuzzFindings, StrayCommaOutsideBracketsIsASyntaxErrorNotAHang) {
  TempDir dir;
  const std::string cases[][2] = {
      {"# a comment\n, broken off the comment\n" + test::kGoodScenario, "2"},
      {", y\n", "1"},
      {"- 1\n, 2\n", "2"},
  };
  for (const auto& [yaml, line] : cases) {
    const std::string path = dir.write("scenario.yaml", yaml);
    expect_contains(test::load_error(path),
                    {path + ":" + line, "YAML syntax error", "remove the stray character"});
  }
  // Empty documents (stray '---' or '...') are not mistaken for a stuck parser.
  const std::string path = dir.write("scenario.yaml", test::kGoodScenario + "---\n...\n");
  EXPECT_NO_THROW(load_scenario(path));
}

// `row: {count: 4294967296}` added particles one by one for minutes before running out of memory.
TEST(ReaderFuzzFindings, RowCountBeyondTheLimitIsRefusedAtOnce) {
  TempDir dir;
  std::string yaml = test::kGoodScenario;
  const std::string list = yaml.substr(yaml.find("  list:\n    - {id: 0"),
                                       yaml.find("bonds:") - yaml.find("  list:\n    - {id: 0"));
  test::replace_once(yaml, list, "  row: {count: 4294967296, spacing: 0.4, radius: 0.2}\n");
  const std::string path = dir.write("scenario.yaml", yaml);
  expect_contains(test::load_error(path), {"particles.row.count", "4294967296", "limit of 1e+08"});
}

// exchange_fuzzer: a LAMMPS data header line of only a vertical tab survived trim (which knew
// ' ', '\t' and '\r') but split into no words, and the header reader took the first of none.
TEST(ReaderFuzzFindings, LammpsHeaderLineOfOtherWhiteSpaceIsBlank) {
  TempDir dir;
  const std::string data =
      "title\n\v\n1 atoms\n\f \v\n1 atom types\n\nAtoms # bpm/sphere\n\n1 1 1 0.2 2650 0 0 0\n";
  const ExchangeStructure s = read_lammps_data(dir.write("structure.data", data));
  ASSERT_EQ(s.particles.id.size(), 1u);
  EXPECT_EQ(s.particles.radius[0], 0.1);
  // The fuzzer's input itself: a MUSEN line and stray bytes, refused with the file and line.
  using namespace std::string_literals;  // the input holds NUL bytes
  const std::string bad = "0 100 1 1 5 0.2\n0 \0\0\0s\n1 bond types\n\n-0.4 4.4\n\v\n"s;
  EXPECT_THROW(read_lammps_data(dir.write("bad.data", bad)), InputError);
}

}  // namespace
}  // namespace bpm
