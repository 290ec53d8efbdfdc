// `bpmkit run` stopped from outside (issue 11, items 2 and 3): killed with SIGKILL at a random
// moment after its first checkpoint, its folder's CSV tables and frames.pvd parse and hold every
// output time up to the last one written, and `--resume` then ends with the same bytes as a run
// that was never stopped. SIGTERM ends the run cleanly: exit status 143, summary.json "interrupted"
// with a checkpoint, from which it resumes to the same bytes too.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "bpmkit_child.hpp"
#include "bpmkit_process.hpp"
#include "common/test_files.hpp"
#include "resume_scenario.hpp"

namespace bpm {
namespace {

using test::TempDir;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Lines written so far to a streamed table (0 if it does not exist yet).
std::ptrdiff_t lines_in(const std::string& path) {
  const std::string text = test::read_text(path);
  return std::count(text.begin(), text.end(), '\n');
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

/// A streamed table: whole lines, a header, every row as many fields as the header, numbers from
/// column numeric_from on; returns the first column of each row (the time).
std::vector<std::string> check_table(const std::string& path, std::size_t numeric_from = 0) {
  const std::string text = test::read_text(path);
  EXPECT_FALSE(text.empty()) << path;
  if (text.empty()) return {};
  EXPECT_EQ(text.back(), '\n') << path << " ends inside a row";
  const std::vector<std::string> lines = lines_of(text);
  const std::size_t columns = fields_of(lines[0]).size();
  std::vector<std::string> first;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> f = fields_of(lines[i]);
    EXPECT_EQ(f.size(), columns) << path << " row " << i;
    for (std::size_t c = numeric_from; c < f.size(); ++c) {
      char* end = nullptr;
      std::strtod(f[c].c_str(), &end);
      EXPECT_EQ(*end, '\0') << path << " row " << i << ": " << f[c];
    }
    first.push_back(f.empty() ? "" : f[0]);
  }
  return first;
}

/// Output times strictly increasing at a constant interval: none missing.
void expect_every_output_time(const std::vector<std::string>& times) {
  ASSERT_GE(times.size(), 3u);
  const double interval = std::stod(times[1]) - std::stod(times[0]);
  for (std::size_t i = 1; i < times.size(); ++i) {
    EXPECT_NEAR(std::stod(times[i]) - std::stod(times[i - 1]), interval, 1e-6 * interval)
        << "output " << i;
  }
}

/// frames.pvd: a whole collection whose frames (and walls) exist whole; returns the frames' times
/// as written (part 0; the walls, part 1, have the same times).
std::vector<std::string> check_pvd(const std::string& dir) {
  const std::string pvd = test::read_text(dir + "/frames.pvd");
  EXPECT_TRUE(pvd.ends_with("</Collection>\n</VTKFile>\n")) << pvd;
  std::vector<std::string> times;
  for (const std::string& line : lines_of(pvd)) {
    const auto t = line.find("timestep=\""), f = line.find("file=\"");
    if (t == std::string::npos || f == std::string::npos) continue;
    if (line.find("part=\"0\"") != std::string::npos)
      times.push_back(line.substr(t + 10, line.find('"', t + 10) - t - 10));
    const std::string file = line.substr(f + 6, line.find('"', f + 6) - f - 6);
    EXPECT_TRUE(test::read_text(dir + "/" + file).ends_with("</VTKFile>\n"))
        << file << " is not whole";
  }
  return times;
}

/// Everything a killed run leaves must be valid up to its last output.
void check_streamed_folder(const std::string& dir) {
  const std::vector<std::string> probe_times = check_table(dir + "/probes.csv");
  const std::vector<std::string> wall_times = check_table(dir + "/walls.csv");
  check_table(dir + "/bond_breaks.csv", 5);
  expect_every_output_time(probe_times);
  // Rows are written before the frame: a kill in between leaves one more row than frames.
  EXPECT_TRUE(wall_times.size() == probe_times.size() ||
              wall_times.size() + 1 == probe_times.size());
  const std::vector<std::string> frame_times = check_pvd(dir);
  ASSERT_TRUE(frame_times.size() == probe_times.size() ||
              frame_times.size() + 1 == probe_times.size())
      << frame_times.size() << " frames, " << probe_times.size() << " probe rows";
  for (std::size_t i = 0; i < frame_times.size(); ++i)
    EXPECT_EQ(frame_times[i], probe_times[i]) << "frame " << i;
}

void expect_same_results(const std::string& expected, const std::string& actual) {
  for (const char* name :
       {"final_state.csv", "probes.csv", "walls.csv", "bond_breaks.csv", "frames.pvd"}) {
    const std::string e = test::read_text(expected + "/" + name);
    ASSERT_FALSE(e.empty()) << name;
    EXPECT_TRUE(e == test::read_text(actual + "/" + name)) << name << " differs after resuming";
  }
}

std::string summary_status(const std::string& dir) {
  return nlohmann::json::parse(test::read_text(dir + "/summary.json"))
      .value("status", std::string());
}

/// A run that lasts a few seconds, with output every 10 steps and a checkpoint every 200.
std::string long_scenario(const TempDir& tmp) {
  test::ResumeScenario s;
  s.nx = s.ny = s.nz = 7;
  s.max_steps = 3000;
  s.every_steps = 10;
  s.checkpoint_every = 200;
  return test::write_resume_scenario(tmp, s);
}

TEST(RunSignals, KilledRunLeavesValidFilesAndResumesBitIdentical) {
  TempDir tmp;
  long_scenario(tmp);
  const test::Outcome reference =
      test::run_bpmkit("run scenario.yaml --out reference", tmp.path(""));
  ASSERT_EQ(reference.status, 0) << reference.output;

  const unsigned seed = std::random_device{}();
  SCOPED_TRACE("kill delay seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  test::BpmkitChild child({"run", "scenario.yaml", "--out", "killed"}, tmp.path(""),
                          tmp.path("killed.log"));
  ASSERT_TRUE(child.wait_until([&] {
    return std::filesystem::exists(tmp.path("killed/checkpoint.bin"));
  })) << "the run ended before its first checkpoint: "
      << test::read_text(tmp.path("killed.log"));
  std::this_thread::sleep_for(
      std::chrono::milliseconds(std::uniform_int_distribution<int>(0, 400)(rng)));
  child.signal(SIGKILL);
  const int status = child.wait();
  if (!WIFSIGNALED(status))
    GTEST_SKIP() << "the run finished before the kill (machine too fast for this size)";

  EXPECT_EQ(summary_status(tmp.path("killed")), "running");
  check_streamed_folder(tmp.path("killed"));

  const test::Outcome resumed = test::run_bpmkit("run scenario.yaml --resume killed", tmp.path(""));
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resumed from the checkpoint at step"), std::string::npos)
      << resumed.output;
  EXPECT_EQ(summary_status(tmp.path("killed")), "finished");
  expect_same_results(tmp.path("reference"), tmp.path("killed"));
}

TEST(RunSignals, TerminatedRunIsInterruptedWithACheckpointAndResumes) {
  TempDir tmp;
  long_scenario(tmp);
  const test::Outcome reference =
      test::run_bpmkit("run scenario.yaml --out reference", tmp.path(""));
  ASSERT_EQ(reference.status, 0) << reference.output;

  test::BpmkitChild child({"run", "scenario.yaml", "--out", "stopped"}, tmp.path(""),
                          tmp.path("stopped.log"));
  ASSERT_TRUE(child.wait_until([&] {
    return lines_in(tmp.path("stopped/probes.csv")) > 5;
  })) << test::read_text(tmp.path("stopped.log"));
  child.signal(SIGTERM);
  const int status = child.wait();
  const std::string log = test::read_text(tmp.path("stopped.log"));
  ASSERT_TRUE(WIFEXITED(status)) << log;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << log;
  EXPECT_NE(log.find("--resume stopped"), std::string::npos) << log;

  const nlohmann::json summary =
      nlohmann::json::parse(test::read_text(tmp.path("stopped/summary.json")));
  EXPECT_EQ(summary.value("status", ""), "interrupted");
  EXPECT_EQ(summary.value("stop_reason", ""), "interrupted");
  ASSERT_TRUE(summary.contains("checkpoint") && summary["checkpoint"].is_string())
      << summary.dump(2);
  EXPECT_TRUE(std::filesystem::exists(tmp.path("stopped/checkpoint.bin")));
  check_streamed_folder(tmp.path("stopped"));

  // Another scenario's checkpoint is refused before the folder is touched.
  tmp.write("edited.yaml", test::read_text(tmp.path("scenario.yaml")) + "# edited\n");
  const test::Outcome refused = test::run_bpmkit("run edited.yaml --resume stopped", tmp.path(""));
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("another scenario"), std::string::npos) << refused.output;
  EXPECT_EQ(summary_status(tmp.path("stopped")), "interrupted");

  const test::Outcome resumed =
      test::run_bpmkit("run scenario.yaml --resume stopped", tmp.path(""));
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_results(tmp.path("reference"), tmp.path("stopped"));
  EXPECT_FALSE(std::filesystem::exists(tmp.path("stopped/checkpoint.bin")));
}

TEST(RunSignals, ResumeUsageErrors) {
  TempDir tmp;
  long_scenario(tmp);
  const test::Outcome both =
      test::run_bpmkit("run scenario.yaml --resume a --overwrite", tmp.path(""));
  EXPECT_EQ(both.status, 2) << both.output;
  EXPECT_NE(both.output.find("--overwrite"), std::string::npos) << both.output;
  const test::Outcome none = test::run_bpmkit("run scenario.yaml --resume missing", tmp.path(""));
  EXPECT_EQ(none.status, 2) << none.output;
  EXPECT_NE(none.output.find("no run to resume"), std::string::npos) << none.output;
}

TEST(RunSignals, AFolderWhoseRunIsStillGoingIsRefused) {
  // --overwrite would delete the files a live run is writing, --resume would write beside it.
  TempDir tmp;
  test::ResumeScenario s;  // long_scenario's, ten times as long: it is killed below anyway
  s.nx = s.ny = s.nz = 7;
  s.max_steps = 30000;
  s.every_steps = 10;
  s.checkpoint_every = 200;
  test::write_resume_scenario(tmp, s);
  test::BpmkitChild child({"run", "scenario.yaml", "--out", "busy"}, tmp.path(""), tmp.path("busy.log"));
  ASSERT_TRUE(child.wait_until([&] {
    return lines_in(tmp.path("busy/probes.csv")) > 2;
  })) << test::read_text(tmp.path("busy.log"));
  for (const char* command : {"run scenario.yaml --out busy --overwrite", "run scenario.yaml --resume busy"}) {
    const test::Outcome refused = test::run_bpmkit(command, tmp.path(""));
    EXPECT_EQ(refused.status, 2) << command << "\n" << refused.output;
    EXPECT_NE(refused.output.find("still running"), std::string::npos) << command << "\n" << refused.output;
  }
  ASSERT_TRUE(child.running()) << "the run ended before the checks: make the scenario longer";
  EXPECT_EQ(summary_status(tmp.path("busy")), "running");
  // Killed without a chance to say so, its folder still says "running" but is taken.
  child.signal(SIGKILL);
  child.wait();
  std::string text = test::read_text(tmp.path("scenario.yaml"));
  const auto at = text.find("max_steps: 30000");
  ASSERT_NE(at, std::string::npos) << text;
  tmp.write("short.yaml", text.replace(at, 16, "max_steps: 100"));
  const test::Outcome taken = test::run_bpmkit("run short.yaml --out busy --overwrite", tmp.path(""));
  EXPECT_EQ(taken.status, 0) << taken.output;
  EXPECT_EQ(summary_status(tmp.path("busy")), "finished");
}

}  // namespace
}  // namespace bpm
