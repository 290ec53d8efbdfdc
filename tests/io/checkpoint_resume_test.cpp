// Checkpoint and resume (scenario/checkpoint.hpp, issue 11 item 3): a run interrupted at step N and
// resumed from its checkpoint ends with the same bytes as one that ran 2N steps straight through
// (final_state.csv, every table, every frame), with bonds breaking and contacts on, for 1 and 2
// OpenMP threads; and a checkpoint from another scenario, another version or a damaged one is
// refused with an error naming the file and the fix.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/parallel.hpp"
#include "io/output_folder.hpp"
#include "io_test_util.hpp"
#include "resume_scenario.hpp"
#include "scenario/checkpoint.hpp"
#include "scenario/scenario_run.hpp"

namespace bpm {
namespace {

using test::ResumeScenario;
using test::TempDir;

/// Sets the OpenMP thread count for one scope.
class Threads {
 public:
  explicit Threads(int n) : saved_(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~Threads() { omp_set_num_threads(saved_); }
  Threads(const Threads&) = delete;
  Threads& operator=(const Threads&) = delete;

 private:
  int saved_;
};

std::string status_of(const std::string& dir) {
  return nlohmann::json::parse(test::read_text(dir + "/summary.json"))
      .value("status", std::string());
}

/// The result files that must match byte for byte (the frames too, when there are few).
std::vector<std::string> compared_files(const std::string& dir) {
  std::vector<std::string> names{"final_state.csv", "probes.csv", "walls.csv", "bond_breaks.csv"};
  if (std::filesystem::exists(dir + "/frames.pvd")) {
    names.push_back("frames.pvd");
    for (const auto& e : std::filesystem::directory_iterator(dir + "/frames")) {
      names.push_back("frames/" + e.path().filename().string());
    }
  }
  return names;
}

void expect_same_files(const std::string& expected_dir, const std::string& actual_dir) {
  for (const std::string& name : compared_files(expected_dir)) {
    const std::string expected = test::read_text(expected_dir + "/" + name);
    ASSERT_FALSE(expected.empty()) << name;
    EXPECT_TRUE(expected == test::read_text(actual_dir + "/" + name))
        << name << " differs after resuming";
  }
  EXPECT_EQ(compared_files(expected_dir), compared_files(actual_dir));
}

/// 2N steps straight through.
ScenarioRunResult run_straight(const std::string& scenario_path, const std::string& dir) {
  Scenario scenario = load_scenario(scenario_path);
  return run_scenario(scenario, dir);
}

/// N steps, interrupted as by a signal (a checkpoint is written), then resumed to 2N.
ScenarioRunResult run_interrupted_and_resumed(const std::string& scenario_path,
                                              const std::string& dir, std::int64_t interrupt_at) {
  {
    Scenario scenario = load_scenario(scenario_path);
    OutputFolder folder(dir, "run", scenario_outputs(scenario), false);
    ScenarioRunOptions options;
    options.interrupt_when = [&](const Simulation& sim) { return sim.steps() == interrupt_at; };
    const ScenarioRunResult first = run_scenario(scenario, folder, options);
    EXPECT_EQ(first.status, "interrupted");
    EXPECT_EQ(first.summary.steps, interrupt_at);
    EXPECT_EQ(status_of(dir), "interrupted");
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + kCheckpointFile));
    EXPECT_FALSE(std::filesystem::exists(dir + "/final_state.csv"));
  }
  Scenario scenario = load_scenario(scenario_path);
  OutputFolder folder = OutputFolder::resume(dir, "run", scenario_outputs(scenario));
  ScenarioRunOptions options;
  options.resume = true;
  ScenarioRunResult second = run_scenario(scenario, folder, options);
  EXPECT_EQ(second.status, "finished");
  EXPECT_EQ(second.resumed_from_step, interrupt_at);
  EXPECT_EQ(status_of(dir), "finished");
  EXPECT_FALSE(std::filesystem::exists(dir + "/" + kCheckpointFile))
      << "a finished run leaves no checkpoint";
  return second;
}

TEST(CheckpointResume, InterruptedAndResumedRunIsBitIdentical) {
  TempDir tmp;
  ResumeScenario s;
  s.max_steps = 120;
  s.every_steps = 7;  // the interruption (step 60) falls between two outputs
  const std::string path = test::write_resume_scenario(tmp, s);
  const ScenarioRunResult straight = run_straight(path, tmp.path("straight"));
  // The comparison means something only if bonds broke and contacts acted on both sides of N.
  ASSERT_TRUE(load_scenario(path).model.bonds.breakable);
  const std::string breaks = test::read_text(tmp.path("straight/bond_breaks.csv"));
  ASSERT_GT(std::count(breaks.begin(), breaks.end(), '\n'), 3) << breaks;
  EXPECT_GT(straight.energies.contact, 0.0);

  const ScenarioRunResult resumed = run_interrupted_and_resumed(path, tmp.path("resumed"), 60);
  expect_same_files(tmp.path("straight"), tmp.path("resumed"));
  EXPECT_EQ(resumed.frames, straight.frames);
  EXPECT_EQ(resumed.summary.steps, straight.summary.steps);
}

TEST(CheckpointResume, PeriodicCheckpointsAndTwoThreadsAreBitIdentical) {
  // More particles and pairs than kParallelMinItems: every parallel loop runs on 2 threads.
  TempDir tmp;
  ResumeScenario s;
  s.nx = 17;
  s.ny = 17;
  s.nz = 15;
  s.max_steps = 40;
  s.every_steps = 10;
  s.checkpoint_every = 15;
  s.vtk = false;
  ASSERT_GT(s.nx * s.ny * s.nz, kParallelMinItems);
  const std::string path = test::write_resume_scenario(tmp, s);
  {
    const Threads one(1);
    run_straight(path, tmp.path("straight"));
  }
  const std::string breaks = test::read_text(tmp.path("straight/bond_breaks.csv"));
  ASSERT_GT(std::count(breaks.begin(), breaks.end(), '\n'), 3) << breaks;
  const Threads two(2);
  run_interrupted_and_resumed(path, tmp.path("resumed"), 23);
  expect_same_files(tmp.path("straight"), tmp.path("resumed"));
}

/// An interrupted run's folder and its checkpoint, for the error tests.
struct Interrupted {
  TempDir tmp;
  std::string scenario, dir;
  Interrupted() {
    ResumeScenario s;
    s.max_steps = 40;
    scenario = test::write_resume_scenario(tmp, s);
    dir = tmp.path("run");
    Scenario loaded = load_scenario(scenario);
    OutputFolder folder(dir, "run", scenario_outputs(loaded), false);
    ScenarioRunOptions options;
    options.interrupt_when = [](const Simulation& sim) { return sim.steps() == 20; };
    run_scenario(loaded, folder, options);
  }
  std::string checkpoint() const { return dir + "/" + kCheckpointFile; }
  /// The message of the error resuming gives.
  std::string resume_error() const {
    try {
      Scenario loaded = load_scenario(scenario);
      OutputFolder folder = OutputFolder::resume(dir, "run", scenario_outputs(loaded));
      ScenarioRunOptions options;
      options.resume = true;
      run_scenario(loaded, folder, options);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "resuming succeeded";
    return {};
  }
  void patch(std::size_t offset, char c) const {
    std::fstream f(checkpoint(), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(offset));
    f.put(c);
  }
};

TEST(CheckpointResume, DamagedCheckpointIsRefused) {
  const Interrupted run;
  const auto size = std::filesystem::file_size(run.checkpoint());
  run.patch(size - 100, '\x7f');
  test::expect_contains(run.resume_error(),
                        {run.checkpoint(), "damaged", "checksum", "--overwrite"});
}

TEST(CheckpointResume, TruncatedCheckpointIsRefused) {
  const Interrupted run;
  std::filesystem::resize_file(run.checkpoint(), 50);
  test::expect_contains(run.resume_error(), {run.checkpoint(), "damaged", "--overwrite"});
}

TEST(CheckpointResume, ForeignFileIsRefused) {
  const Interrupted run;
  run.tmp.write("run/checkpoint.bin", "id,x\n1,2\n");
  test::expect_contains(run.resume_error(), {run.checkpoint(), "not a bpmkit checkpoint"});
}

TEST(CheckpointResume, OtherVersionIsRefused) {
  const Interrupted run;
  // The version string follows the magic (8 bytes), the format (4) and its length (8).
  run.patch(20, '9');
  test::expect_contains(run.resume_error(),
                        {run.checkpoint(), "written by bpmkit 9", "this is bpmkit"});
}

TEST(CheckpointResume, OtherScenarioIsRefused) {
  const Interrupted run;
  std::ofstream(run.scenario, std::ios::app) << "# edited\n";
  test::expect_contains(run.resume_error(), {run.checkpoint(), "another scenario", run.scenario});
}

TEST(CheckpointResume, OtherModelIsRefused) {
  const Interrupted run;
  std::string csv = test::read_text(run.tmp.path("particles.csv"));
  csv.replace(csv.find(",0.001\n"), 7, ",0.00101\n");  // one radius
  run.tmp.write("particles.csv", csv);
  test::expect_contains(run.resume_error(), {run.checkpoint(), "another model"});
}

TEST(CheckpointResume, MissingCheckpointIsRefused) {
  const Interrupted run;
  std::filesystem::remove(run.checkpoint());
  test::expect_contains(run.resume_error(),
                        {run.checkpoint(), "no checkpoint", "checkpoint_every"});
}

TEST(CheckpointResume, FinishedRunIsNotResumed) {
  TempDir tmp;
  ResumeScenario s;
  s.max_steps = 10;
  const std::string path = test::write_resume_scenario(tmp, s);
  run_straight(path, tmp.path("run"));
  Scenario loaded = load_scenario(path);
  try {
    OutputFolder::resume(tmp.path("run"), "run", scenario_outputs(loaded));
    ADD_FAILURE() << "resuming a finished run succeeded";
  } catch (const InputError& e) {
    test::expect_contains(e.what(), {tmp.path("run"), "finished", "--overwrite"});
  }
}

TEST(CheckpointResume, DivergedRunKeepsItsStateAndIsNotResumed) {
  TempDir tmp;
  ResumeScenario s;
  s.max_steps = 20;
  std::string yaml = test::read_text(test::write_resume_scenario(tmp, s));
  yaml.replace(yaml.find("force: [0.4, 0.2, 2.5]"), 22,
               "force: [1e308, 1e308, 0]");  // overflows at once
  // Without particle contacts: the Verlet list would cast the infinite positions to cell
  // numbers (undefined behaviour) before the step's finiteness check.
  const std::string contacts = "contacts: {particle_particle: true, bonded: superimpose}\n";
  yaml.erase(yaml.find(contacts), contacts.size());
  const std::string path = tmp.write("scenario.yaml", yaml);
  const std::string dir = tmp.path("run");
  {
    Scenario scenario = load_scenario(path);
    EXPECT_THROW(run_scenario(scenario, dir), DivergenceError);
  }
  const nlohmann::json summary = nlohmann::json::parse(test::read_text(dir + "/summary.json"));
  EXPECT_EQ(summary.value("status", ""), "diverged");
  test::expect_contains(summary.value("reason", ""), {"diverged", "non-finite"});
  EXPECT_TRUE(std::filesystem::exists(dir + "/final_state.csv"));
  Scenario scenario = load_scenario(path);
  try {
    OutputFolder::resume(dir, "run", scenario_outputs(scenario),
                         [&] { check_checkpoint(dir + "/" + kCheckpointFile, scenario); });
    ADD_FAILURE() << "resuming a diverged run succeeded";
  } catch (const InputError& e) {
    test::expect_contains(e.what(), {kCheckpointFile, "diverged at step 1", "would diverge again"});
  }
  EXPECT_EQ(status_of(dir), "diverged") << "a refused resume leaves the folder as it was";
}

TEST(CheckpointResume, CheckpointEveryIsParsed) {
  TempDir tmp;
  ResumeScenario s;
  s.checkpoint_every = 25;
  EXPECT_EQ(load_scenario(test::write_resume_scenario(tmp, s)).output.checkpoint_every_steps, 25);
  std::string yaml = test::read_text(tmp.path("scenario.yaml"));
  yaml.replace(yaml.find("{steps: 25}"), 11, "{steps: 25, time: 1}");
  test::expect_contains(test::load_error(tmp.write("scenario.yaml", yaml)),
                        {"output.checkpoint_every", "one of steps or time"});
}

}  // namespace
}  // namespace bpm
