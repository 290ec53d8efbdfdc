// What the reader fuzzer (reader_fuzz_test.cpp) found, each as the input that showed it; every one
// used to run for minutes or for ever and is now an InputError naming the line and the fix.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <string>

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

}  // namespace
}  // namespace bpm
