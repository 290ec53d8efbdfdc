// Runs that used to hang, succeed with nothing done or end in NaN (issue 11, item 6) are refused
// before any step with an InputError that gives the estimate and the fix: a time step that
// extreme but finite values make 0 or 1e-149 s, an end time below half a step, max_steps short of
// end_time, an endless CSV line, coincident particle centres, and a compression test whose fitted
// stiffness is negative.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/simulation.hpp"
#include "io/csv_table.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_run.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::edited;
using test::expect_contains;
using test::replace_once;
using test::TempDir;

/// The message of the InputError that running `s` into `out` raises; a test failure if none.
std::string run_error(Scenario& s, const std::string& out) {
  try {
    run_scenario(s, out);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

/// kGoodScenario running to `stop` (a YAML flow map) instead of 200 steps.
std::string with_stop(std::string yaml, const std::string& stop) {
  replace_once(yaml, "stop:\n  max_steps: 200\n", "stop: " + stop + "\n");
  return yaml;
}

TEST(RunLimits, AbsurdlySmallAutomaticStepIsRefused) {
  TempDir dir;
  // E_b = 1e300 Pa: the stability limit is 2.3e-149 s, 5e148 steps for one second (it used to run
  // for ever).
  const std::string yaml = with_stop(edited("youngs_modulus: 200e9", "youngs_modulus: 1e300"), "{end_time: 1}");
  const std::string path = dir.write("scenario.yaml", yaml);
  expect_contains(test::load_error(path),
                  {fmt::format("{}:{}", path, test::line_of(yaml, "stop:")), "stop.end_time", "5.34e+148 steps",
                   "1.87398e-149 s", "auto", "below 1e-15 of end_time", "Young's moduli"});
  // Given a max_steps, the same step is refused for the step count (not cut short at max_steps).
  expect_contains(test::load_error(dir.write("scenario.yaml", with_stop(edited("youngs_modulus: 200e9",
                                                                                 "youngs_modulus: 1e300"),
                                                                          "{end_time: 1, max_steps: 1000}"))),
                  {"stop.end_time", "below 1e-15 of end_time"});
  // An explicit step too.
  std::string explicit_step = with_stop(test::kGoodScenario, "{end_time: 1e5}");
  replace_once(explicit_step, "time_step: auto", "time_step: 1e-12");
  expect_contains(test::load_error(dir.write("scenario.yaml", explicit_step)),
                  {"stop.end_time", "1e+17 steps", "integrator.time_step"});
}

TEST(RunLimits, OverflowingStabilityBoundIsNamed) {
  TempDir dir;
  // A density of 1e-200 overflows the frequency bound: it used to read as "no bond acts on a free
  // particle".
  const std::string yaml = edited("density: 7850", "density: 1e-200");
  const std::string path = dir.write("scenario.yaml", yaml);
  expect_contains(test::load_error(path), {fmt::format("{}:{}", path, test::line_of(yaml, "integrator:")),
                                           "not finite", "particle 1", "densities"});
}

TEST(RunLimits, EndTimeBelowHalfAStepIsRefused) {
  TempDir dir;
  // The step is about 4.2e-5 s: 1e-9 s used to "succeed" with 0 steps.
  const std::string yaml = with_stop(test::kGoodScenario, "{end_time: 1e-9}");
  const std::string path = dir.write("scenario.yaml", yaml);
  expect_contains(test::load_error(path), {fmt::format("{}:{}", path, test::line_of(yaml, "stop:")),
                                           "stop.end_time", "below half a time step", "0 steps",
                                           "at least one step"});
  // One step's worth runs one step.
  Scenario s = load_scenario(dir.write("scenario.yaml", with_stop(test::kGoodScenario, "{end_time: 4.2e-5}")));
  Simulation sim(s.model, s.time_step);
  EXPECT_EQ(sim.run(s.stop).steps, 1);
}

TEST(RunLimits, MaxStepsShortOfEndTimeIsRefused) {
  TempDir dir;
  const std::string yaml = with_stop(test::kGoodScenario, "{end_time: 1, max_steps: 1000}");
  const std::string path = dir.write("scenario.yaml", yaml);
  const Scenario fine = load_scenario(dir.write("fine.yaml", with_stop(test::kGoodScenario, "{end_time: 1}")));
  const auto needed = static_cast<long long>(std::llround(1.0 / fine.time_step));
  expect_contains(test::load_error(path),
                  {fmt::format("{}:{}", path, test::line_of(yaml, "stop:")), "stop.max_steps",
                   fmt::format("needs about {} steps", needed), fmt::format("at least {}", needed)});
  // Enough steps load; with rest_speed both are guards of a run meant to end at rest.
  EXPECT_NO_THROW(load_scenario(
      dir.write("scenario.yaml", with_stop(test::kGoodScenario, fmt::format("{{end_time: 1, max_steps: {}}}", needed)))));
  EXPECT_NO_THROW(load_scenario(
      dir.write("scenario.yaml", with_stop(test::kGoodScenario, "{end_time: 1, max_steps: 1000, rest_speed: 1e-9}"))));
}

TEST(RunLimits, EndlessCsvLineIsRefusedAtTheLimit) {
  TempDir dir;
  std::string yaml = test::kGoodScenario;
  replace_once(yaml,
               "  list:\n    - {id: 0, position: [0, 0, 0], radius: 0.2}\n    - {id: 1, position: "
               "[0.4, 0, 0], radius: 0.2}\n"
               "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n",
               "  file: /dev/zero\n");
  // /dev/zero used to be read as one endless line.
  expect_contains(test::load_error(dir.write("scenario.yaml", yaml)),
                  {"/dev/zero:1", "longer than the limit of 1048576 bytes (1 MiB)"});
  // A real file: the limit is on the line, not the file.
  const std::string csv = dir.write("long.csv", "id,x,y,z,radius\n0,0,0,0,0.2\n" + std::string(kMaxCsvLineBytes + 1, '1') + "\n");
  try {
    read_csv(csv, "scenario.yaml:11: particles.file");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    expect_contains(e.what(), {csv + ":3", "1048576 bytes"});
  }
  dir.write("ok.csv", "id,x,y,z,radius\n0,0,0,0," + std::string(kMaxCsvLineBytes - 8, '0') + "\n");
  EXPECT_EQ(read_csv(dir.path("ok.csv"), "here").size(), 1u);
}

TEST(RunLimits, CoincidentCentresAreNamed) {
  TempDir dir;
  // A duplicated particle (id 7 where id 1 is) with contacts on: NaN in the first step, reported
  // as a divergence that blamed the time step.
  std::string yaml = edited("    density: 7850\n",
                            "    density: 7850\n    contact: {youngs_modulus: 200e9, poisson_ratio: 0.3, "
                            "restitution: 0.5, friction: 0.3}\n");
  replace_once(yaml, "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n",
               "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n    - {id: 7, position: [0.4, 0, 0], radius: 0.2}\n");
  replace_once(yaml, "damping:", "contacts: {particle_particle: true}\ndamping:");
  Scenario s = load_scenario(dir.write("scenario.yaml", yaml));
  expect_contains(run_error(s, dir.path("out")), {"particles 1 and 7", "same centre", "remove the duplicate"});
  // Touching particles, and close but distinct centres (1e-3 R) run.
  replace_once(yaml, "{id: 7, position: [0.4, 0, 0]", "{id: 7, position: [0.4, 0.0002, 0]");
  Scenario close = load_scenario(dir.write("scenario.yaml", yaml));
  EXPECT_NO_THROW({ Simulation sim(close.model, close.time_step); });
}

TEST(RunLimits, NegativeFittedStiffnessIsRefused) {
  TempDir dir;
  // The small cylinder without its bonds: loose particles are pushed along, and the fit gave
  // K = -0.16 N/m, E = -105 Pa (-4873 Pa in the issue), reported as a result.
  const std::string folder = std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/";
  std::string yaml = test::read_text(folder + "compression.yaml");
  replace_once(yaml, "file: structure/particles.csv", "file: " + folder + "structure/particles.csv");
  replace_once(yaml, "bonds:\n  file: structure/bonds.csv", "bonds:\n  list: []\n#");
  Scenario s = load_scenario(dir.write("scenario.yaml", yaml));
  expect_contains(run_error(s, dir.path("out")), {"compression", "fitted stiffness K = -", "not positive", "the sample has no bonds"});
}

}  // namespace
}  // namespace bpm
