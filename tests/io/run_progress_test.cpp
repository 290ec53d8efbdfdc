// The progress line of a DEM run (scenario/run_progress.hpp): its text, the plain lines off a terminal,
// the break summaries, and the stride that keeps its cost down.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "dem/simulation.hpp"
#include "scenario/run_progress.hpp"
#include "scenario/scenario.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::expect_contains;

TEST(RunProgress, TextHoldsEveryField) {
  ProgressSnapshot s;
  s.step = 120000;
  s.time = 1.5e-3;
  s.fraction = 0.5;
  s.wall_seconds = 75.0;
  s.eta_seconds = 4000.0;
  s.bond_updates_per_second = 2.1e7;
  s.max_speed = 3e-6;
  s.rest_speed = 1e-9;
  s.bonds_broken = 140;
  expect_contains(progress_text(s),
                  {"step 120000", "t = 0.0015 s", "(50.0 %)", "wall 1m15s", "ETA 1h06m",
                   "2.1e+07 bond updates/s", "speed 3e-06 m/s (rest < 1e-09)", "140 broken"});
  // Unknown percent and ETA, no rest criterion: left out, not shown as nonsense.
  const std::string bare = progress_text(ProgressSnapshot{});
  EXPECT_EQ(bare.find('%'), std::string::npos) << bare;
  EXPECT_EQ(bare.find("ETA"), std::string::npos) << bare;
  EXPECT_EQ(bare.find("speed"), std::string::npos) << bare;
}

TEST(RunProgress, PlanFollowsTheStopCriteria) {
  const Scenario pull =
      load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/03_breakage/pull_to_failure.yaml");
  EXPECT_DOUBLE_EQ(progress_plan(pull).end_time, 1.6);
  EXPECT_EQ(progress_plan(pull).rest_speed, 0.0);
  const Scenario cantilever =
      load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/01_cantilever/case1_tbbm.yaml");
  EXPECT_DOUBLE_EQ(progress_plan(cantilever).rest_speed, 1e-9);
  const Scenario compression = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) +
                                             "/04_compression/small_cylinder/compression.yaml");
  // target strain 0.005 at strain rate 2 / s
  EXPECT_DOUBLE_EQ(progress_plan(compression).end_time, 0.0025);
}

/// The bar of examples/03_breakage pulled apart, watched by a reporter printing at every check.
TEST(RunProgress, BreaksAfterTheLastClockReadAreSummarisedAtTheEnd) {
  // The clock is read at a stride of steps; bonds that break after the last read (as in a run whose
  // bonds fail in its last steps) must still reach the closing summary (StepMonitor::run_ended).
  Scenario s = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/03_breakage/pull_to_failure.yaml");
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  RunProgress::Settings settings;
  settings.terminal = false;
  {
    RunProgress progress(progress_plan(s), out, settings);
    Simulation sim(s.model, s.time_step);
    sim.step();
    progress.after_step(sim);  // the last clock read: nothing broken yet
    ASSERT_TRUE(s.model.bonds.breaks.empty());
    s.model.bonds.breaks.push_back({0, 1, BreakMode::tension, Vec3{}});  // a break in the last steps
    progress.run_ended(sim);
  }  // finish(): the closing summary
  std::rewind(out);
  std::string text;
  for (int c; (c = std::fgetc(out)) != EOF;) text.push_back(static_cast<char>(c));
  std::fclose(out);
  expect_contains(text, {"1 bond broke (total 1)"});
}

TEST(RunProgress, PlainLinesAndBreakSummariesOffATerminal) {
  Scenario s =
      load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/03_breakage/pull_to_failure.yaml");
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  RunProgress::Settings settings;
  settings.terminal = false;
  settings.line_interval_s = 0.0;
  settings.break_interval_s = 0.0;
  std::int64_t calls = 0, steps = 0;
  std::size_t breaks = 0;
  {
    RunProgress progress(progress_plan(s), out, settings);
    // Counts the calls on the way through.
    struct Counting : StepMonitor {
      RunProgress* inner;
      std::int64_t* calls;
      std::int64_t after_step(const Simulation& sim) override {
        ++*calls;
        return inner->after_step(sim);
      }
      // Breaks after the last clock read reach the summary through here (a fast run may read
      // the clock for the last time before the first break).
      void run_ended(const Simulation& sim) override { inner->run_ended(sim); }
    } counting;
    counting.inner = &progress;
    counting.calls = &calls;
    const ScopedStepMonitor watching(counting);
    Simulation sim(s.model, s.time_step);
    const RunSummary r = sim.run(s.stop);
    steps = r.steps;
    breaks = s.model.bonds.breaks.size();
  }
  EXPECT_EQ(installed_step_monitor, nullptr);
  ASSERT_GT(breaks, 0u);
  std::rewind(out);
  std::string text;
  for (int c; (c = std::fgetc(out)) != EOF;) text.push_back(static_cast<char>(c));
  std::fclose(out);
  expect_contains(text, {"progress: step ", "bond updates/s", "broken", "(total "});
  EXPECT_EQ(text.find('\r'), std::string::npos) << "a carriage return off a terminal";
  // The clock is read at a stride of steps (about every 50 ms), not at every step.
  EXPECT_LT(calls, steps / 10) << calls << " calls in " << steps << " steps";
}

}  // namespace
}  // namespace bpm
