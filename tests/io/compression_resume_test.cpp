// Checkpoint and resume of a compression test (issue 11 item 3): a test interrupted at step N and
// resumed from its checkpoint ends with the same final_state.csv, force_displacement.csv,
// walls.csv, bond_breaks.csv and summary.json (but its timing) as one run straight through, with
// contacts on, masses scaled, bonds breaking and the test running on past its peak to failure; and
// a checkpoint of a plain run, or of another scenario, is refused with an error naming the file and
// the fix.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "io/output_folder.hpp"
#include "io_test_util.hpp"
#include "resume_scenario.hpp"
#include "scenario/checkpoint.hpp"
#include "scenario/scenario_run.hpp"

namespace bpm {
namespace {

using test::TempDir;

/// A 3 x 3 x 6 bonded lattice of slightly jittered grains with weak bonds, compressed past its
/// peak: bonds break from the start, the stress peaks at step ~395, the test ends by failure at
/// step 500.
std::string write_compression_scenario(const TempDir& dir) {
  std::uint64_t state = 7;
  auto noise = [&] {  // a fixed LCG: the same lattice on every machine
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 1e-5;
  };
  std::string csv = "id,x,y,z,radius\n";
  int id = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 6; ++k) {
        csv += fmt::format("{},{:.17g},{:.17g},{:.17g},0.001\n", id++, 2e-3 * i + noise(),
                           2e-3 * j + noise(), 2e-3 * k);
      }
    }
  }
  dir.write("lattice.csv", csv);
  return dir.write("compression.yaml", R"(particle_materials:
  grain:
    density: 2500
    contact: {youngs_modulus: 1e9, poisson_ratio: 0.25, restitution: 0.5, friction: 0.3}
bond_materials:
  cement:
    model: tbbm
    youngs_modulus: 1e9
    poisson_ratio: 0.25
    radius: 5e-4
    tensile_strength: {distribution: weibull, scale: 1e5, shape: 4}
    shear_strength: 1e5
seed: 3
particles: {material: grain, file: lattice.csv}
bonds: {material: cement, auto: {max_gap: 1e-4}}
contacts: {particle_particle: true, bonded: superimpose}
damping: {particle: 0.3}
compression:
  platen_material: grain
  strain_rate: 20
  target_strain: 0.01
  fit_window: [0.3, 1.0]
  failure_drop: 0.5
  max_strain: 0.03
  curve_points: 100
  mass_scaling: 4
output:
  vtk: false
  checkpoint_every: {steps: 50}
)");
}

/// Runs the scenario at `path` into `dir`, interrupted (as by a signal) at step `at`.
ScenarioRunResult run_interrupted(const std::string& path, const std::string& dir,
                                  std::int64_t at) {
  Scenario scenario = load_scenario(path);
  OutputFolder folder(dir, "run", scenario_outputs(scenario), false);
  ScenarioRunOptions options;
  options.interrupt_when = [at](const Simulation& sim) { return sim.steps() == at; };
  return run_scenario(scenario, folder, options);
}

ScenarioRunResult resume(const std::string& path, const std::string& dir) {
  Scenario scenario = load_scenario(path);
  OutputFolder folder = OutputFolder::resume(dir, "run", scenario_outputs(scenario));
  ScenarioRunOptions options;
  options.resume = true;
  return run_scenario(scenario, folder, options);
}

/// The message of the InputError resuming the run in `dir` gives.
std::string resume_error(const std::string& path, const std::string& dir) {
  try {
    resume(path, dir);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "resuming succeeded";
  return {};
}

/// summary.json without what differs between two runs of the same test: timing, the process, the
/// folder in the paths, the step resumed from.
nlohmann::json comparable_summary(const std::string& dir) {
  nlohmann::json s = nlohmann::json::parse(test::read_text(dir + "/summary.json"));
  for (const char* key : {"bond_updates_per_second", "wall_s", "started", "ended", "pid",
                          "command_line", "resumed_from_step"}) {
    s.erase(key);
  }
  for (auto& file : s["outputs"]) {
    file = std::filesystem::path(file.get<std::string>()).filename().string();
  }
  return s;
}

void expect_same_results(const std::string& expected_dir, const std::string& actual_dir) {
  for (const char* name :
       {"final_state.csv", "force_displacement.csv", "walls.csv", "bond_breaks.csv"}) {
    const std::string expected = test::read_text(expected_dir + "/" + name);
    ASSERT_FALSE(expected.empty()) << name;
    EXPECT_TRUE(expected == test::read_text(actual_dir + "/" + name))
        << name << " differs after resuming";
  }
  EXPECT_EQ(comparable_summary(expected_dir), comparable_summary(actual_dir));
}

class CompressionResume : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = write_compression_scenario(tmp_);
    Scenario scenario = load_scenario(path_);
    straight_ = run_scenario(scenario, tmp_.path("straight"));
  }
  TempDir tmp_;
  std::string path_;
  ScenarioRunResult straight_;
};

TEST_F(CompressionResume, InterruptedAndResumedTestIsBitIdentical) {
  // The comparison means something only if the peak comes before the interruptions, and breaks
  // and the failure after them: step 400 (a curve point and a periodic checkpoint) and 413
  // (neither).
  ASSERT_TRUE(straight_.compression.has_value());
  EXPECT_EQ(straight_.compression->stop, "failure");
  const CompressionResult& c = *straight_.compression;
  EXPECT_GT(straight_.summary.steps, 400);
  const double dt = c.time_step;
  const auto at_400 =
      std::find_if(c.curve.begin(), c.curve.end(),
                   [dt](const CompressionPoint& pt) { return pt.time > 399.5 * dt; });
  ASSERT_NE(at_400, c.curve.end());
  EXPECT_LT(c.peak_strain, at_400->strain);
  EXPECT_GT(c.curve.back().bonds_broken, at_400->bonds_broken);
  EXPECT_GT(straight_.energies.contact, 0.0);
  EXPECT_FALSE(std::filesystem::exists(tmp_.path("straight/") + kCheckpointFile))
      << "a finished test leaves no checkpoint";
  for (const std::int64_t at : {400, 413}) {
    const std::string dir = tmp_.path(fmt::format("resumed_{}", at));
    const ScenarioRunResult first = run_interrupted(path_, dir, at);
    EXPECT_EQ(first.status, "interrupted");
    EXPECT_EQ(first.summary.steps, at);
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + kCheckpointFile));
    EXPECT_FALSE(std::filesystem::exists(dir + "/final_state.csv"));
    const ScenarioRunResult second = resume(path_, dir);
    EXPECT_EQ(second.status, "finished");
    EXPECT_EQ(second.resumed_from_step, at);
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + kCheckpointFile));
    expect_same_results(tmp_.path("straight"), dir);
    ASSERT_TRUE(second.compression.has_value());
    EXPECT_EQ(second.compression->stiffness, straight_.compression->stiffness);
    EXPECT_EQ(second.compression->peak_stress, straight_.compression->peak_stress);
    EXPECT_EQ(second.compression->curve.size(), straight_.compression->curve.size());
  }
}

TEST_F(CompressionResume, CheckpointOfAnotherScenarioOrRunIsRefused) {
  const std::string dir = tmp_.path("compression");
  run_interrupted(path_, dir, 200);
  const std::string checkpoint = dir + "/" + kCheckpointFile;
  const std::string compression_bytes = test::read_text(checkpoint);

  // A plain run's checkpoint (a scenario without a compression section) in the test's folder.
  test::ResumeScenario plain;
  plain.max_steps = 40;
  const std::string plain_path = test::write_resume_scenario(tmp_, plain);  // scenario.yaml
  const std::string plain_dir = tmp_.path("plain");
  run_interrupted(plain_path, plain_dir, 20);
  const std::string plain_checkpoint = plain_dir + "/" + kCheckpointFile;
  std::filesystem::copy_file(plain_checkpoint, checkpoint,
                             std::filesystem::copy_options::overwrite_existing);
  test::expect_contains(resume_error(path_, dir), {checkpoint, "written by a plain run", path_,
                                                   "compression test", "--overwrite"});

  // The reverse: the test's checkpoint in the plain run's folder.
  tmp_.write("plain_copy.bin", compression_bytes);
  std::filesystem::copy_file(tmp_.path("plain_copy.bin"), plain_checkpoint,
                             std::filesystem::copy_options::overwrite_existing);
  test::expect_contains(resume_error(plain_path, plain_dir),
                        {plain_checkpoint, "written by a compression test", "plain run"});

  // The test's own checkpoint after its scenario file changed.
  std::ofstream(checkpoint, std::ios::binary | std::ios::trunc) << compression_bytes;
  std::ofstream(path_, std::ios::app) << "# edited\n";
  test::expect_contains(resume_error(path_, dir), {checkpoint, "another scenario", path_});
}

TEST_F(CompressionResume, CheckpointEveryIsAllowed) {
  EXPECT_EQ(load_scenario(path_).output.checkpoint_every_steps, 50);
  const auto names = scenario_outputs(load_scenario(path_));
  EXPECT_NE(std::find(names.begin(), names.end(), kCheckpointFile), names.end());
}

}  // namespace
}  // namespace bpm
