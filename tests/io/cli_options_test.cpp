// The options of every command (cli/global_options.hpp): --quiet, --verbose, --threads, before or
// after the subcommand; summary.json records the thread count, the seed and the command line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <string>

#include "bpmkit_process.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::Outcome;
using test::run_bpmkit;
using test::TempDir;

nlohmann::json summary_of(const TempDir& dir, const std::string& out) {
  return nlohmann::json::parse(test::read_text(dir.path(out + "/summary.json")));
}

TEST(CliOptions, QuietPrintsOnlyTheResultLines) {
  TempDir dir;
  dir.write("scenario.yaml", test::kGoodScenario);
  const Outcome o = run_bpmkit("run scenario.yaml --out out --quiet", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("stopped by max_steps after 200 steps"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("3 particles"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("wrote"), std::string::npos) << o.output;
}

TEST(CliOptions, VerboseAddsTheTimeStepsDerivation) {
  TempDir dir;
  dir.write("scenario.yaml", test::kGoodScenario);
  const Outcome o = run_bpmkit("--verbose run scenario.yaml --out out", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  test::expect_contains(
      o.output, {"3 particles", "time step: safety factor 0.8", "OpenMP threads", "stopped by"});
  EXPECT_EQ(run_bpmkit("run scenario.yaml --out out2 --quiet --verbose", dir.path("")).status, 2);
}

TEST(CliOptions, VerboseGenerateStatesItsSettings) {
  TempDir dir;
  const std::string spec = std::string(BPMKIT_EXAMPLES_DIR) + "/02_generate/small_box.yml";
  const Outcome o = run_bpmkit("--verbose generate " + spec + " --out out", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  test::expect_contains(o.output, {"settings: porosity 0.45; relaxation to a largest overlap of 0.01 R",
                                   "eta_r = 1.1, r_b = 0.8 min(R_i, R_j)", "bonds ("});
  const Outcome plain = run_bpmkit("generate " + spec + " --out out2", dir.path(""));
  EXPECT_EQ(plain.output.find("settings:"), std::string::npos) << plain.output;
}

TEST(CliOptions, ThreadsAreAppliedAndRecordedWithTheSeedAndCommandLine) {
  TempDir dir;
  dir.write("scenario.yaml", test::kGoodScenario);
  for (const int threads : {1, 2}) {
    const std::string out = "out" + std::to_string(threads);
    const std::string args =
        "run scenario.yaml --out " + out + " --threads " + std::to_string(threads);
    const Outcome o = run_bpmkit(args, dir.path(""));
    ASSERT_EQ(o.status, 0) << o.output;
    const nlohmann::json summary = summary_of(dir, out);
    EXPECT_EQ(summary["threads"], threads);
    EXPECT_EQ(summary["seed"], 1);  // the default
    EXPECT_NE(summary["command_line"].get<std::string>().find(args), std::string::npos)
        << summary["command_line"];
  }
  // Without --threads, OMP_NUM_THREADS holds (the child inherits this process's environment).
  ::setenv("OMP_NUM_THREADS", "1", 1);
  const Outcome o = run_bpmkit("run scenario.yaml --out env", dir.path(""));
  ::unsetenv("OMP_NUM_THREADS");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(summary_of(dir, "env")["threads"], 1);
  for (const std::string bad : {"--threads 0", "--threads two", "--threads"}) {
    EXPECT_EQ(run_bpmkit("run scenario.yaml --out bad " + bad, dir.path("")).status, 2) << bad;
  }
}

}  // namespace
}  // namespace bpm
