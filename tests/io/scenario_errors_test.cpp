// Every kind of bad scenario input raises an InputError that names the file, the YAML key path (or
// the CSV line) and the line number, so the user can find and fix it.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::edited;
using test::kGoodScenario;
using test::TempDir;

/// Loads `yaml` as scenario.yaml and checks that the error message names the file, the line that
/// contains `line_text`, and every fragment (typically the key path and the complaint).
void expect_error(const std::string& yaml, const std::string& line_text, const std::vector<std::string>& fragments) {
  TempDir dir;
  const std::string path = dir.write("scenario.yaml", yaml);
  const std::string message = test::load_error(path);
  const int line = test::line_of(yaml, line_text);
  ASSERT_GT(line, 0) << "'" << line_text << "' is not in the scenario";
  EXPECT_NE(message.find(fmt::format("{}:{}", path, line)), std::string::npos)
      << "expected file and line " << path << ":" << line << " in: " << message;
  test::expect_contains(message, fragments);
}

TEST(ScenarioErrors, GoodScenarioLoads) {
  TempDir dir;
  EXPECT_NO_THROW(load_scenario(dir.write("scenario.yaml", kGoodScenario)));
}

TEST(ScenarioErrors, UnknownKey) {
  expect_error(edited("    poisson_ratio: 0.3\n", "    poisson_ratio: 0.3\n    poisson_rato: 0.3\n"), "poisson_rato",
               {"bond_materials.beam.poisson_rato", "unknown key", "allowed keys"});
  expect_error(kGoodScenario + "gravty: [0, 0, -9.81]\n", "gravty", {"gravty", "unknown key"});
  expect_error(edited("    fix: all", "    fix: all\n    fixed: all"), "fixed:", {"boundary_conditions[0].fixed", "unknown key"});
}

TEST(ScenarioErrors, DuplicateYamlKey) {
  expect_error(edited("    density: 7850\n", "    density: 7850\n    density: 1000\n"), "density: 1000",
               {"particle_materials.steel.density", "duplicate key"});
}

TEST(ScenarioErrors, MissingField) {
  expect_error(edited("    poisson_ratio: 0.3\n", ""), "  beam:", {"bond_materials.beam.poisson_ratio", "missing"});
  expect_error(edited("stop:\n  max_steps: 200\n", ""), "particle_materials:", {"stop", "missing"});
  expect_error(edited("{id: 1, position: [0.4, 0, 0], radius: 0.2}", "{id: 1, radius: 0.2}"), "{id: 1, radius",
               {"particles.list[1].position", "missing"});
}

TEST(ScenarioErrors, RadiusNotPositive) {
  for (const std::string bad : {"0", "-0.2"}) {
    expect_error(edited("[0.4, 0, 0], radius: 0.2}", "[0.4, 0, 0], radius: " + bad + "}"), "[0.4, 0, 0]",
                 {"particles.list[1].radius", "greater than 0"});
  }
  expect_error(edited("    radius: 0.2\n", "    radius: 0\n"), "    radius: 0", {"bond_materials.beam.radius", "greater than 0"});
}

TEST(ScenarioErrors, PoissonRatioOutOfRange) {
  for (const std::string bad : {"0.5", "-0.1", "0.7"}) {
    expect_error(edited("poisson_ratio: 0.3", "poisson_ratio: " + bad), "poisson_ratio",
                 {"bond_materials.beam.poisson_ratio", "[0, 0.5)"});
  }
}

TEST(ScenarioErrors, UnknownBondModelListsValidKeys) {
  expect_error(edited("model: tbbm", "model: tbm"), "model: tbm",
               {"bond_materials.beam.model", "'tbm'", "pbm", "brendel", "ebbm", "tbbm", "obermayr"});
}

TEST(ScenarioErrors, OptionThatDoesNotApplyToTheModel) {
  expect_error(edited("    radius: 0.2\n", "    radius: 0.2\n    kappa: 3\n"), "kappa", {"bond_materials.beam.kappa", "pbm"});
  expect_error(edited("    radius: 0.2\n", "    radius: 0.2\n    radius_multiplier: 1\n"), "radius_multiplier",
               {"radius_multiplier", "not both"});
  expect_error(edited("    radius: 0.2\n", "    radius: 0.2\n    shear_stiffness: stiff\n"), "shear_stiffness",
               {"bond_materials.beam.shear_stiffness", "euler_bernoulli"});
}

TEST(ScenarioErrors, BondToMissingParticle) {
  expect_error(edited("list: [[0, 1], [1, 2]]", "list: [[0, 1], [1, 7]]"), "[[0, 1], [1, 7]]",
               {"bonds.list[1]", "particle id 7", "does not exist"});
}

TEST(ScenarioErrors, DuplicateBond) {
  expect_error(edited("list: [[0, 1], [1, 2]]", "list: [[0, 1], [1, 2], [1, 0]]"), "[1, 0]",
               {"bonds.list[2]", "duplicate bond 1-0"});
}

TEST(ScenarioErrors, SelfBond) {
  expect_error(edited("list: [[0, 1], [1, 2]]", "list: [[0, 1], [1, 1]]"), "[1, 1]", {"bonds.list[1]", "itself"});
}

TEST(ScenarioErrors, ZeroLengthBond) {
  expect_error(edited("{id: 1, position: [0.4, 0, 0]", "{id: 1, position: [0, 0, 0]"), "list: [[0, 1]",
               {"bonds.list[0]", "zero length"});
}

TEST(ScenarioErrors, DuplicateParticleId) {
  expect_error(edited("{id: 2, position", "{id: 1, position"), "{id: 1, position: [0.8",
               {"particles.list[2]", "duplicate particle id 1"});
}

TEST(ScenarioErrors, TimeStepAboveLimit) {
  TempDir dir;
  const double limit = load_scenario(dir.write("good.yaml", kGoodScenario)).time_step_limit;
  expect_error(edited("time_step: auto", "time_step: 1e-3"), "time_step: 1e-3",
               {"integrator.time_step", "0.001 s", fmt::format("{:.6g} s", limit), "stability limit"});
  expect_error(edited("time_step: auto", "time_step: auto\n  safety_factor: 1.5"), "safety_factor",
               {"integrator.safety_factor", "(0, 1]"});
}

TEST(ScenarioErrors, WrongType) {
  expect_error(edited("density: 7850", "density: [7850]"), "density:", {"particle_materials.steel.density", "expected a number"});
  expect_error(edited("density: 7850", "density: heavy"), "density:", {"particle_materials.steel.density", "'heavy'"});
  expect_error(edited("max_steps: 200", "max_steps: 2.5"), "max_steps", {"stop.max_steps", "integer"});
  expect_error(edited("every_steps: 50", "every_steps: 50\n  vtk: maybe"), "vtk:", {"output.vtk", "true or false"});
  expect_error(edited("  - particles: [0]\n", "  - particles: 0\n"), "  - particles: 0", {"boundary_conditions[0].particles", "expected a list"});
  expect_error(edited("force: [0, -1e5, 0]", "force: [0, -1e5]"), "force:", {"loads[0].force", "3 numbers"});
  expect_error(edited("  beam:\n    model", "  beam: tbbm\n  other:\n    model"), "  beam: tbbm", {"bond_materials.beam", "expected a map"});
}

TEST(ScenarioErrors, NonFiniteNumbersAreRefused) {
  expect_error(edited("density: 7850", "density: .nan"), "density:", {"particle_materials.steel.density", "finite"});
  expect_error(edited("youngs_modulus: 200e9", "youngs_modulus: .inf"), "youngs_modulus", {"youngs_modulus", "finite"});
  expect_error(edited("youngs_modulus: 200e9", "youngs_modulus: 1e999"), "youngs_modulus", {"youngs_modulus", "finite"});
}

TEST(ScenarioErrors, UnknownNames) {
  expect_error(edited("  material: steel", "  material: iron"), "material: iron", {"particles.material", "'iron'", "steel"});
  expect_error(edited("  material: beam", "  material: rod"), "material: rod", {"bonds.material", "'rod'", "beam"});
  expect_error(edited("fix: all", "fix: [x, q]"), "fix: [x, q]", {"boundary_conditions[0].fix[1]", "'q'"});
  expect_error(edited("  - particles: [0]\n", "  - particles: [5]\n"), "particles: [5]", {"boundary_conditions[0].particles[0]", "id 5"});
}

TEST(ScenarioErrors, OutOfRangeSettings) {
  expect_error(edited("particle: 0.7", "particle: 1.0"), "particle: 1.0", {"damping.particle", "[0, 1)"});
  expect_error(edited("damping:\n  particle: 0.7", "damping:\n  bond: -1"), "bond: -1", {"damping.bond", "negative"});
  expect_error(edited("ramp_time: 0.01", "ramp_time: -1"), "ramp_time", {"loads[0].ramp_time", "negative"});
}

TEST(ScenarioErrors, ExactlyOneSourceOrSet) {
  expect_error(edited("  material: steel\n", "  material: steel\n  row: {count: 3, spacing: 0.4, radius: 0.2}\n"), "row:",
               {"particles.row", "only one of"});
  expect_error(edited("  material: beam\n  list: [[0, 1], [1, 2]]\n", "  material: beam\n"), "bonds:", {"bonds", "file, list, auto"});
  expect_error(edited("  - particles: [2]\n", "  - particles: [2]\n    region: {box: {min: [0, 0, 0], max: [1, 1, 1]}}\n"),
               "region:", {"loads[0].region", "only one of"});
}

TEST(ScenarioErrors, EmptyRegion) {
  expect_error(edited("  - particles: [0]\n", "  - region: {box: {min: [5, 5, 5], max: [6, 6, 6]}}\n"), "region:",
               {"boundary_conditions[0].region", "no particle"});
  expect_error(edited("  - particles: [0]\n", "  - region: {box: {min: [1, 0, 0], max: [0, 1, 1]}}\n"), "region:",
               {"boundary_conditions[0].region.box.max", "min"});
}

TEST(ScenarioErrors, StopNeedsEndTimeOrMaxSteps) {
  expect_error(edited("  max_steps: 200", "  rest_speed: 1e-9"), "stop:", {"stop", "end_time or max_steps"});
}

TEST(ScenarioErrors, ConstraintOrLoadThatDoesNothing) {
  expect_error(edited("    fix: all\n", ""), "  - particles: [0]", {"boundary_conditions[0]", "constrains nothing"});
  expect_error(edited("    fix: all\n", "    fix: [x]\n    velocity: [1, ~, ~]\n"), "velocity:",
               {"boundary_conditions[0].velocity", "both fixed and prescribed"});
  expect_error(edited("    force: [0, -1e5, 0]\n", ""), "  - particles: [2]", {"loads[0]", "applies nothing"});
}

TEST(ScenarioErrors, ProbeNames) {
  expect_error(edited("{name: tip, particles: [2]}", "{name: tip, particles: [2]}\n    - {name: tip, particles: [1]}"),
               "{name: tip, particles: [1]}", {"output.probes[1].name", "duplicate probe name"});
  expect_error(edited("{name: tip,", "{name: 'tip,x',"), "tip,x", {"output.probes[0].name", "not a valid probe name"});
}

TEST(ScenarioErrors, YamlSyntaxError) {
  expect_error(edited("list: [[0, 1], [1, 2]]", "list: [[0, 1], [1, 2]\ndamping2: 1"), "damping2", {"YAML syntax error"});
}

TEST(ScenarioErrors, MissingOrEmptyFile) {
  TempDir dir;
  const std::string missing = dir.path("nope.yaml");
  EXPECT_NE(test::load_error(missing).find(missing), std::string::npos);
  const std::string empty = dir.write("empty.yaml", "# nothing\n");
  const std::string message = test::load_error(empty);
  EXPECT_NE(message.find(empty), std::string::npos) << message;
  EXPECT_NE(message.find("empty"), std::string::npos) << message;
}

// ---------------------------------------------------------------------------------------------
// CSV inputs: the error names the CSV file and its line.

/// Writes the CSV next to a scenario that reads particles from it; returns the error message.
std::string particle_csv_error(const TempDir& dir, const std::string& csv) {
  dir.write("particles.csv", csv);
  const std::string yaml = edited(
      "  list:\n    - {id: 0, position: [0, 0, 0], radius: 0.2}\n    - {id: 1, position: [0.4, 0, 0], radius: 0.2}\n"
      "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n",
      "  file: particles.csv\n");
  return test::load_error(dir.write("scenario.yaml", yaml));
}

TEST(ScenarioErrors, MalformedParticleCsvLine) {
  TempDir dir;
  const std::string csv = dir.path("particles.csv");
  test::expect_contains(particle_csv_error(dir, "id,x,y,z,radius\n0,0,0,0,0.2\n1,0.4,0,0,0.2\n2,0.8,abc,0,0.2\n"),
                  {csv + ":4", "'y'", "'abc'"});
  test::expect_contains(particle_csv_error(dir, "0,0,0,0,0.2\n1,0.4,0,0\n2,0.8,0,0,0.2\n"), {csv + ":2", "5 or 6 columns"});
  test::expect_contains(particle_csv_error(dir, "# comment\n\n0,0,0,0,0.2\n1.5,0.4,0,0,0.2\n"), {csv + ":4", "'id'", "integer"});
  test::expect_contains(particle_csv_error(dir, "id,x,y,z,r\n0,0,0,0,0.2\n"), {csv + ":1", "header"});
  test::expect_contains(particle_csv_error(dir, "0,0,0,0,0.2\n1,0.4,0,0,0\n2,0.8,0,0,0.2\n"), {csv + ":2", "radius"});
  test::expect_contains(particle_csv_error(dir, "0,0,0,0,0.2\n1,0.4,0,0,0.2\n1,0.8,0,0,0.2\n"), {csv + ":3", "duplicate particle id 1"});
  test::expect_contains(particle_csv_error(dir, "0,0,0,0,0.2,steel\n1,0.4,0,0,0.2,iron\n2,0.8,0,0,0.2\n"), {csv + ":2", "'iron'"});
  test::expect_contains(particle_csv_error(dir, "0,0,0,0,nan\n"), {csv + ":1", "finite"});
}

TEST(ScenarioErrors, MalformedBondCsvLine) {
  TempDir dir;
  const std::string csv = dir.write("bonds.csv", "i,j\n0,1\n1,9\n");
  const std::string yaml = edited("  list: [[0, 1], [1, 2]]\n", "  file: bonds.csv\n");
  const std::string path = dir.write("scenario.yaml", yaml);
  test::expect_contains(test::load_error(path), {csv + ":3", "particle id 9", "does not exist"});
  dir.write("bonds.csv", "0,1\n1,2\n2,1\n");
  test::expect_contains(test::load_error(path), {csv + ":3", "duplicate bond"});
  dir.write("bonds.csv", "0,1,0.2,beam,extra\n");
  test::expect_contains(test::load_error(path), {csv + ":1", "2 to 4 columns"});
  dir.write("bonds.csv", "i,j,material,radius\n0,1,beam,0.2\n");
  test::expect_contains(test::load_error(path), {csv + ":1", "header"});
  dir.write("bonds.csv", "i,j,radius\n0,1,-0.2\n");
  test::expect_contains(test::load_error(path), {csv + ":2", "greater than 0"});
}

TEST(ScenarioErrors, BadBondStrength) {
  const std::string radius = "    radius: 0.2\n";
  expect_error(edited(radius, radius + "    tensile_strength: -5e6\n"), "tensile_strength",
               {"bond_materials.beam.tensile_strength", "greater than 0"});
  expect_error(edited(radius, radius + "    shear_strength: {distribution: gauss, mean: 1e6, std_dev: 1e5}\n"),
               "shear_strength", {"bond_materials.beam.shear_strength.distribution", "unknown distribution 'gauss'",
                                  "normal or weibull"});
  expect_error(edited(radius, radius + "    tensile_strength: {distribution: weibull, scale: 1e6}\n"),
               "tensile_strength", {"bond_materials.beam.tensile_strength.shape", "missing"});
  expect_error(edited(radius, radius + "    tensile_strength: {distribution: normal, mean: 1e6, shape: 3}\n"),
               "tensile_strength", {"bond_materials.beam.tensile_strength.distribution", "mean and std_dev"});
  expect_error(kGoodScenario + "seed: -3\n", "seed: -3", {"seed", "non-negative"});
}

TEST(ScenarioErrors, MissingCsvFile) {
  const std::string yaml = edited("  list: [[0, 1], [1, 2]]\n", "  file: no_such_bonds.csv\n");
  expect_error(yaml, "no_such_bonds.csv", {"bonds.file", "cannot open", "no_such_bonds.csv"});
}

}  // namespace
}  // namespace bpm
