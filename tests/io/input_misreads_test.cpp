// Inputs that used to load silently with a different meaning (issue 11, item 6) are refused with
// an InputError naming the file, the line or key, and the fix; a spreadsheet's CSV with a
// byte-order mark, which used to be refused, is read.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io_test_util.hpp"
#include "scenario/scenario.hpp"

namespace bpm {
namespace {

using test::edited;
using test::expect_contains;
using test::kGoodScenario;
using test::replace_once;
using test::TempDir;

/// kGoodScenario with `description: VALUE` in front of its last section (`output`, which is
/// optional, so a description that swallows it still gives a complete scenario).
std::string with_description_before_output(const std::string& value) {
  return edited("output:\n", "description: " + value + "\noutput:\n");
}

TEST(InputMisreads, UnclosedQuoteNearTheEndIsRefused) {
  TempDir dir;
  for (const std::string value : {"\"three particles", "'three particles"}) {
    const std::string yaml = with_description_before_output(value);
    // Trailing blank lines and CRLF line ends do not hide it.
    for (const std::string tail : {"", "\n\n", "# end\n"}) {
      const std::string path = dir.write("scenario.yaml", yaml + tail);
      expect_contains(test::load_error(path),
                      {fmt::format("{}:{}", path, test::line_of(yaml, "description:")),
                       "never closed", "closing quote"});
    }
    std::string crlf;
    for (const char c : yaml) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const std::string path = dir.write("scenario.yaml", crlf);
    expect_contains(
        test::load_error(path),
        {fmt::format("{}:{}", path, test::line_of(yaml, "description:")), "never closed"});
  }
}

TEST(InputMisreads, ClosedQuotesStillLoad) {
  TempDir dir;
  // A quoted value may span lines; a block scalar ending the file keeps its text.
  Scenario s = load_scenario(
      dir.write("scenario.yaml", with_description_before_output("\"three\n  particles\"")));
  EXPECT_EQ(s.description, "three particles");
  s = load_scenario(
      dir.write("scenario.yaml", kGoodScenario + "description: 'it''s \"quoted\"'\n\n"));
  EXPECT_EQ(s.description, "it's \"quoted\"");
  s = load_scenario(
      dir.write("scenario.yaml", kGoodScenario + "description: |\n  two\n  lines\n\n"));
  EXPECT_EQ(s.description, "two\nlines\n");
}

TEST(InputMisreads, SecondYamlDocumentIsRefused) {
  TempDir dir;
  const std::string yaml = kGoodScenario + "---\nstop:\n  max_steps: 5\n";
  const std::string path = dir.write("scenario.yaml", yaml);
  expect_contains(test::load_error(path),
                  {fmt::format("{}:{}", path, test::line_of(yaml, "max_steps: 5") - 1),
                   "second YAML document", "remove the '---' line"});
  // A leading '---', an end marker '...' and a stray '---' with nothing after it lose nothing.
  EXPECT_NO_THROW(load_scenario(dir.write("scenario.yaml", "---\n" + kGoodScenario + "...\n")));
  EXPECT_NO_THROW(
      load_scenario(dir.write("scenario.yaml", kGoodScenario + "---\n# nothing here\n")));
}

/// kGoodScenario reading its bonds from `file`, with a fixed time step (without bonds `auto` has
/// no stability limit to derive, which would hide the misread behind another error).
std::string with_bond_file(const std::string& file) {
  std::string yaml = edited("  list: [[0, 1], [1, 2]]\n", "  file: " + file + "\n");
  replace_once(yaml, "time_step: auto", "time_step: 1e-6");
  return yaml;
}

/// `yaml` (a kGoodScenario variant) reading its particles from `file`.
std::string with_particle_file(std::string yaml, const std::string& file) {
  replace_once(yaml,
               "  list:\n    - {id: 0, position: [0, 0, 0], radius: 0.2}\n    - {id: 1, position: "
               "[0.4, 0, 0], radius: 0.2}\n"
               "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n",
               "  file: " + file + "\n");
  return yaml;
}

TEST(InputMisreads, EmptyBondsCsvIsRefused) {
  TempDir dir;
  const std::string path = dir.write("scenario.yaml", with_bond_file("bonds.csv"));
  for (const std::string csv : {"i,j\n", "", "# exported bonds\n\ni,j,radius\n"}) {
    const std::string csv_path = dir.write("bonds.csv", csv);
    expect_contains(test::load_error(path), {csv_path, "no bond rows", "bonds: {list: []}"});
  }
}

TEST(InputMisreads, EmptyBondListMeansNoBonds) {
  TempDir dir;
  std::string yaml = with_bond_file("bonds.csv");
  replace_once(yaml, "  file: bonds.csv\n", "  list: []\n");
  EXPECT_EQ(load_scenario(dir.write("scenario.yaml", yaml)).model.bonds.size(), 0u);
}

TEST(InputMisreads, CsvPathThatIsAFolderIsRefused) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("parts"));
  const std::string yaml = with_bond_file("parts");
  const std::string path = dir.write("scenario.yaml", yaml);
  expect_contains(test::load_error(path),
                  {fmt::format("{}:{}", path, test::line_of(yaml, "file: parts")), "bonds.file",
                   dir.path("parts"), "is a folder", "bonds: {list: []}"});
  // The particles file too (read_csv itself refuses a folder).
  const std::string particles = with_particle_file(kGoodScenario, "parts");
  expect_contains(test::load_error(dir.write("scenario.yaml", particles)),
                  {fmt::format("{}:{}", path, test::line_of(particles, "file: parts")),
                   "particles.file", "is a folder"});
}

TEST(InputMisreads, CsvWithByteOrderMarkIsRead) {
  TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  const std::string path =
      dir.write("scenario.yaml", with_particle_file(with_bond_file("bonds.csv"), "particles.csv"));
  // As a spreadsheet saves "CSV UTF-8": the mark, a header, CRLF line ends.
  dir.write("particles.csv",
            bom + "id,x,y,z,radius\r\n0,0,0,0,0.2\r\n1,0.4,0,0,0.2\r\n2,0.8,0,0,0.2\r\n");
  dir.write("bonds.csv", bom + "i,j\r\n0,1\r\n1,2\r\n");
  Scenario s = load_scenario(path);
  EXPECT_EQ(s.model.particles.size(), 3u);
  EXPECT_EQ(s.model.bonds.size(), 2u);
  // Without a header the mark sits in front of the first number.
  dir.write("particles.csv", bom + "0,0,0,0,0.2\n1,0.4,0,0,0.2\n2,0.8,0,0,0.2\n");
  dir.write("bonds.csv", bom + "0,1\n1,2\n");
  s = load_scenario(path);
  EXPECT_EQ(s.model.particles.id, (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(s.model.bonds.size(), 2u);
}

}  // namespace
}  // namespace bpm
