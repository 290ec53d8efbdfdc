// Spec files for `bpmkit generate`: a good spec loads; every kind of mistake is an InputError that
// names the file, the line, the key path and what to do.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <string>
#include <vector>

#include "structure/generate_spec.hpp"
#include "structure/mesh_container.hpp"
#include "structure_test_util.hpp"

namespace bpm {
namespace {

using test::TempDir;

const std::string kGoodSpec = R"(description: test
seed: 3
container:
  box: {min: [0, 0, 0], max: [1, 1, 1]}
radii:
  uniform: {min: 0.03, max: 0.05}
packing:
  porosity: 0.45
  overlap_tolerance: 0.01
bonds:
  contact_radius_multiplier: 1.1
  materials:
    soft: 0.4
    stiff: 0.6
output:
  vtk: false
)";

std::string edited(const std::string& from, const std::string& to) {
  std::string s = kGoodSpec;
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}

/// Loads `yaml` and checks the message names file:line (of the line holding `line_text`) and
/// every fragment.
void expect_error(const std::string& yaml, const std::string& line_text, const std::vector<std::string>& fragments) {
  TempDir dir;
  const std::string path = dir.write("spec.yaml", yaml);
  const std::string msg = test::error_of([&] { load_generate_spec(path); });
  const int line = test::line_of(yaml, line_text);
  ASSERT_GT(line, 0) << line_text;
  EXPECT_NE(msg.find(fmt::format("{}:{}", path, line)), std::string::npos) << "expected " << path << ":" << line << " in: " << msg;
  for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "expected '" << f << "' in: " << msg;
}

TEST(GenerateSpec, GoodSpecLoads) {
  TempDir dir;
  const GenerateSpec s = load_generate_spec(dir.write("spec.yaml", kGoodSpec));
  EXPECT_EQ(s.seed, 3u);
  EXPECT_DOUBLE_EQ(s.target.porosity, 0.45);
  EXPECT_DOUBLE_EQ(*s.bond_criterion.contact_radius_multiplier, 1.1);
  ASSERT_EQ(s.bond_materials.size(), 2u);
  EXPECT_EQ(s.bond_materials[1].name, "stiff");
  EXPECT_FALSE(s.write_vtk);
  EXPECT_TRUE(s.write_scenario);
}

TEST(GenerateSpec, UnknownKeys) {
  expect_error(edited("  porosity: 0.45\n", "  porosity: 0.45\n  porosty: 0.4\n"), "porosty", {"packing.porosty", "unknown key", "allowed keys"});
  expect_error(kGoodSpec + "bondz: {}\n", "bondz", {"bondz", "unknown key"});
  expect_error(edited("box: {min", "cube: {min"), "cube:", {"container.cube", "unknown key", "box, cylinder, sphere, stl"});
}

TEST(GenerateSpec, MissingFields) {
  expect_error(edited("radii:\n  uniform: {min: 0.03, max: 0.05}\n", ""), "description", {"radii", "missing required key"});
  expect_error(edited("  porosity: 0.45\n", ""), "packing:", {"packing", "porosity, count"});
  expect_error(edited("{min: 0.03, max: 0.05}", "{min: 0.03}"), "uniform:", {"radii.uniform.max", "missing"});
  expect_error(edited("  contact_radius_multiplier: 1.1\n", ""), "bonds:", {"bonds", "contact_radius_multiplier and/or max_gap"});
}

// Spec files are read like scenarios (YamlField::load_file): issue 11's silent misreads.
TEST(GenerateSpec, SecondDocumentAndUnclosedQuoteAreRefused) {
  const std::string second = kGoodSpec + "---\nseed: 4\n";
  expect_error(second, "seed: 4", {"second YAML document", "remove the '---' line"});
  std::string unclosed = edited("description: test\n", "");
  // The open quote swallows the output section.
  unclosed.insert(unclosed.find("output:\n"), "description: \"cylinder\n");
  expect_error(unclosed, "cylinder", {"never closed", "closing quote"});
}

TEST(GenerateSpec, BadValues) {
  expect_error(edited("{min: 0.03, max: 0.05}", "{min: -0.03, max: 0.05}"), "uniform:", {"radii.uniform.min", "greater than 0"});
  expect_error(edited("{min: 0.03, max: 0.05}", "{min: 0.05, max: 0.03}"), "uniform:", {"radii.uniform.max", "min < max"});
  for (const std::string bad : {"0", "1", "1.5", "-0.2"}) {
    expect_error(edited("porosity: 0.45", "porosity: " + bad), "porosity:", {"packing.porosity", "must be in (0, 1)"});
  }
  expect_error(edited("stiff: 0.6", "stiff: 0.5"), "materials:", {"bonds.materials", "sum to 1"});
  expect_error(edited("contact_radius_multiplier: 1.1", "contact_radius_multiplier: 0.9"), "contact_radius",
               {"bonds.contact_radius_multiplier", "at least 1"});
  expect_error(edited("max: [1, 1, 1]", "max: [1, -1, 1]"), "box:", {"container.box.max", "greater than"});
  expect_error(edited("seed: 3", "seed: 3.5"), "seed:", {"seed", "integer"});
  expect_error(edited("  overlap_tolerance: 0.01\n", "  overlap_tolerance: 0.01\n  on_failure: ignore\n"), "on_failure",
               {"packing.on_failure", "'error' or 'warn'"});
  expect_error(edited("porosity: 0.45", "count: 0"), "count:", {"packing.count", "between 1"});
  expect_error(edited("{min: 0.03, max: 0.05}", "{min: 0.03, max: 0.6}"), "radii:", {"radii", "does not fit"});
  expect_error(edited("porosity: 0.45", "porosity: .nan"), "porosity:", {"packing.porosity", "finite"});
  expect_error(edited("    soft: 0.4\n", "    so ft: 0.4\n"), "so ft", {"bonds.materials.so ft", "letters, digits"});
  expect_error(edited("  uniform: {min: 0.03, max: 0.05}", "  normal: {mean: 0.04, std: 0.01, min: 0.2, max: 0.3}"), "normal:",
               {"radii.normal", "only a fraction"});
  expect_error(edited("porosity: 0.45", "porosity: 0.45\n  count: 10"), "count: 10", {"packing.count", "only one of"});
}

TEST(GenerateSpec, ParticleCountsBeyondTheLimitsAreRefused) {
  // count: 3e9 used to end in a bare std::bad_alloc (and 3e9 was "not an integer").
  expect_error(edited("porosity: 0.45", "count: 3e9"), "count:",
               {"packing.count", "3e+09 particles", "the limit of 1e+08 particles"});
  expect_error(edited("porosity: 0.45", "count: 2.5"), "count:", {"packing.count", "whole number"});
  // The expected count of a porosity target too: R = 1e-4 to 2e-4 m in a 1 m box is about 1e10.
  expect_error(edited("{min: 0.03, max: 0.05}", "{min: 0.0001, max: 0.0002}"), "porosity:",
               {"packing.porosity", "the limit of 1e+08 particles"});
  // Below it, what the memory available now holds: 9e7 particles in 4 GB.
  const std::string problem = particle_count_problem(9e7, 4e9);
  EXPECT_NE(problem.find("4e+06 that fit in the memory available now (4 GB"), std::string::npos) << problem;
  EXPECT_EQ(particle_count_problem(3e6, 4e9), "");
  EXPECT_GT(available_memory_bytes(), 0.0);
}

TEST(GenerateSpec, StlProblemsNameTheFile) {
  TempDir dir;
  const std::string missing = edited("box: {min: [0, 0, 0], max: [1, 1, 1]}", "stl: {file: nothere.stl}");
  const std::string path = dir.write("spec.yaml", missing);
  const std::string msg = test::error_of([&] { load_generate_spec(path); });
  EXPECT_NE(msg.find("nothere.stl"), std::string::npos) << msg;
  EXPECT_NE(msg.find(fmt::format("{}:4: container.stl.file", path)), std::string::npos) << msg;

  auto tris = test::cube_triangles();
  tris.pop_back();
  dir.write("open.stl", test::ascii_stl(tris));
  const std::string open = dir.write("spec2.yaml", edited("box: {min: [0, 0, 0], max: [1, 1, 1]}", "stl: {file: open.stl}"));
  const std::string msg2 = test::error_of([&] { load_generate_spec(open); });
  EXPECT_NE(msg2.find("open.stl"), std::string::npos) << msg2;
  EXPECT_NE(msg2.find("open edges"), std::string::npos) << msg2;

  dir.write("cube.stl", test::ascii_stl(test::cube_triangles()));
  const GenerateSpec s = load_generate_spec(dir.write("spec3.yaml", edited("box: {min: [0, 0, 0], max: [1, 1, 1]}", "stl: {file: cube.stl, scale: 2}")));
  EXPECT_NEAR(s.container->volume(), 8.0, 1e-12);
}

}  // namespace
}  // namespace bpm
