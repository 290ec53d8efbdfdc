// An output folder is one run (issue 11, item 1): a second run into it is refused unless
// --overwrite, which deletes exactly the files the earlier run listed in summary.json; files
// bpmkit did not write are never deleted, and refused where this run would write over them; a
// bad --out fails before any computation; summary.json says "running", then "finished" or
// "failed" with the reason. And stdout is line-buffered, so status lines arrive through a pipe
// while the run goes on.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "bpmkit_process.hpp"
#include "core/error.hpp"
#include "io/output_folder.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::run_bpmkit;
using test::TempDir;

nlohmann::json summary_of(const std::string& folder) {
  return nlohmann::json::parse(test::read_text(folder + "/summary.json"));
}

/// The files under `folder`, relative to it.
std::set<std::string> files_in(const std::string& folder) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file()) names.insert(fs::relative(e.path(), folder).generic_string());
  }
  return names;
}

/// Writes `name` (parent folders created) under `dir`.
void put(const TempDir& dir, const std::string& name, const std::string& content) {
  fs::create_directories(fs::path(dir.path(name)).parent_path());
  dir.write(name, content);
}

const std::string kSmallCylinder = std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/compression.yaml";

TEST(OutputFolder, SecondRunIsRefusedAndNamesOverwrite) {
  TempDir dir;
  dir.write("scenario.yaml", test::kGoodScenario);
  Outcome o = run_bpmkit("run scenario.yaml --out out", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  const std::string first = test::read_text(dir.path("out/final_state.csv"));

  o = run_bpmkit("run scenario.yaml --out out", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("out: holds the results of an earlier `bpmkit run`"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("--overwrite"), std::string::npos) << o.output;
  EXPECT_EQ(test::read_text(dir.path("out/final_state.csv")), first);
  EXPECT_EQ(summary_of(dir.path("out"))["status"], "finished");
}

TEST(OutputFolder, OverwriteRemovesExactlyTheOwnedFilesAndLeavesNoStaleOnes) {
  TempDir dir;
  dir.write("long.yaml", test::kGoodScenario);  // 5 output times, probes, VTK frames
  ASSERT_EQ(run_bpmkit("run long.yaml --out out", dir.path("")).status, 0);
  EXPECT_EQ(summary_of(dir.path("out"))["vtk_frames"], 5);
  // The user's own files beside the results, under names bpmkit does not write.
  put(dir, "out/notes.txt", "mine");
  put(dir, "out/frames/readme.txt", "mine too");

  // Shorter (2 output times) and without probes.
  std::string short_run = test::edited("max_steps: 200", "max_steps: 50");
  test::replace_once(short_run, "  probes:\n    - {name: tip, particles: [2]}\n", "");
  dir.write("short.yaml", short_run);
  const Outcome o = run_bpmkit("run short.yaml --out out --overwrite", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(files_in(dir.path("out")),
            (std::set<std::string>{"final_state.csv", "frames.pvd", "frames/frame_000000.vtp", "frames/frame_000001.vtp",
                                   "frames/readme.txt", "notes.txt", "summary.json"}));
  EXPECT_EQ(test::read_text(dir.path("out/notes.txt")), "mine");
  const auto summary = summary_of(dir.path("out"));
  EXPECT_EQ(summary["status"], "finished");
  EXPECT_EQ(summary["vtk_frames"], 2);
  EXPECT_EQ(summary["owned_files"],
            (nlohmann::json{"final_state.csv", "frames.pvd", "frames/frame_*.vtp", "checkpoint.bin", "summary.json"}));
}

TEST(OutputFolder, ForeignFilesUnderOutputNamesAreRefusedEvenWithOverwrite) {
  TempDir dir;
  dir.write("scenario.yaml", test::kGoodScenario);
  put(dir, "out/probes.csv", "my own measurements\n");
  put(dir, "out/frames/frame_000007.vtp", "<mine/>");
  const Outcome o = run_bpmkit("run scenario.yaml --out out --overwrite", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("did not write"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("probes.csv"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("frames/frame_000007.vtp"), std::string::npos) << o.output;
  EXPECT_EQ(test::read_text(dir.path("out/probes.csv")), "my own measurements\n");
  EXPECT_EQ(files_in(dir.path("out")), (std::set<std::string>{"frames/frame_000007.vtp", "probes.csv"}));

  // Other foreign files do not stand in the way, and stay.
  put(dir, "other/scenario.yaml", test::kGoodScenario);
  ASSERT_EQ(run_bpmkit("run scenario.yaml --out other", dir.path("")).status, 0);
  EXPECT_EQ(test::read_text(dir.path("other/scenario.yaml")), test::kGoodScenario);
}

TEST(OutputFolder, UnwritableOutFailsBeforeComputing) {
  TempDir dir;
  dir.write("blocker", "a file where the folder should go");
  // The DEM takes seconds on this sample; the error must come before it starts.
  const auto start = std::chrono::steady_clock::now();
  Outcome o = run_bpmkit("stiffness --method dem '" + kSmallCylinder + "' --out blocker/out", dir.path(""));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("blocker/out: cannot create the output folder"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("K ="), std::string::npos) << "computed before failing:\n" << o.output;
  EXPECT_LT(seconds, 5.0);

  dir.write("scenario.yaml", test::kGoodScenario);
  o = run_bpmkit("run scenario.yaml --out blocker", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("blocker: is a file, not a folder"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("particles"), std::string::npos) << "printed the run's header:\n" << o.output;
}

TEST(OutputFolder, SummarySaysRunningThenFinished) {
  TempDir dir;
  OutputFolder folder(dir.path("out"), "test", {"result.txt"}, false);
  const auto running = summary_of(dir.path("out"));
  EXPECT_EQ(running["status"], "running");
  EXPECT_EQ(running["command"], "test");
  EXPECT_EQ(running["owned_files"], (nlohmann::json{"result.txt", "summary.json"}));
  EXPECT_GE(running["threads"].get<int>(), 1);
  EXPECT_EQ(running["bpmkit_version"], bpmkit_version());
  folder.run([&] {
    EXPECT_EQ(summary_of(dir.path("out"))["status"], "running");
    folder.write("result.txt", "42\n");
    return nlohmann::json{{"answer", 42}};
  });
  const auto finished = summary_of(dir.path("out"));
  EXPECT_EQ(finished["status"], "finished");
  EXPECT_EQ(finished["answer"], 42);
  EXPECT_EQ(finished["started"], running["started"]);
  EXPECT_TRUE(finished.contains("ended"));
}

TEST(OutputFolder, AnErrorAfterTheClaimMarksTheRunFailed) {
  TempDir dir;
  {
    OutputFolder folder(dir.path("out"), "test", {"result.txt"}, false);
    EXPECT_THROW(folder.run([]() -> nlohmann::json { throw InputError("input.yaml:3", "something is wrong"); }),
                 InputError);
  }
  auto summary = summary_of(dir.path("out"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_EQ(summary["error"], "input.yaml:3: something is wrong");

  // The same through the command: the reference is read after the folder was claimed.
  const Outcome o = run_bpmkit("compare '" + kSmallCylinder + "' --methods ste --reference-from nowhere.json --out cmp",
                               dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  summary = summary_of(dir.path("cmp"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_NE(summary["error"].get<std::string>().find("nowhere.json: cannot be read"), std::string::npos) << summary;
  EXPECT_EQ(summary["command"], "compare");
  EXPECT_NE(summary["command_line"].get<std::string>().find("compare"), std::string::npos);
  // A failed run's folder holds a run too: refused without --overwrite.
  const Outcome again = run_bpmkit("compare '" + kSmallCylinder + "' --methods ste --out cmp", dir.path(""));
  EXPECT_EQ(again.status, 2) << again.output;
  EXPECT_NE(again.output.find("(status: failed)"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("--overwrite"), std::string::npos) << again.output;
}

TEST(OutputFolder, StiffnessWritesItsVtkFilesOnlyIfTheScenarioAsksForVtk) {
  TempDir dir;
  // The small cylinder says `vtk: false`: the STE's map (431 MB on the 8e5-particle box) is skipped.
  Outcome o = run_bpmkit("stiffness --method ste '" + kSmallCylinder + "' --out off", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(files_in(dir.path("off")), (std::set<std::string>{"stiffness.json", "summary.json"}));
  // The same scenario with `vtk: true` (its files named by absolute path) writes the map.
  std::string text = test::read_text(kSmallCylinder);
  const std::string folder = std::filesystem::path(kSmallCylinder).parent_path().string() + "/";
  for (const char* name : {"structure/particles.csv", "structure/bonds.csv"}) {
    const auto at = text.find(std::string("file: ") + name);
    ASSERT_NE(at, std::string::npos) << name;
    text.insert(at + 6, folder);
  }
  const auto vtk = text.find("vtk: false");
  ASSERT_NE(vtk, std::string::npos);
  text.replace(vtk, 10, "vtk: true");
  dir.write("on.yaml", text);
  o = run_bpmkit("stiffness --method ste on.yaml --out on", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(files_in(dir.path("on")), (std::set<std::string>{"stiffness.json", "stiffness_map.vtp", "summary.json"}));
}

TEST(OutputFolder, OverwriteNeverDeletesOutsideTheFolder) {
  TempDir dir;
  dir.write("outside.txt", "keep");
  put(dir, "out/summary.json",
            R"({"status": "finished", "command": "run", "owned_files": ["../outside.txt", ")" + dir.path("outside.txt") +
                R"(", "summary.json", "old.csv"]})");
  put(dir, "out/old.csv", "old");
  { OutputFolder folder(dir.path("out"), "test", {"result.txt"}, true); }
  EXPECT_EQ(test::read_text(dir.path("outside.txt")), "keep");
  EXPECT_FALSE(fs::exists(dir.path("out/old.csv")));
  EXPECT_EQ(summary_of(dir.path("out"))["status"], "running");
}

TEST(OutputFolder, ReadsTheFileListOfAnEarlierVersionsSummary) {
  TempDir dir;
  // bpmkit 0.1.0's `run` listed its files under "outputs" and counted its frames.
  put(dir, "out/summary.json", R"({"stop_reason": "rest", "vtk_frames": 2,
      "outputs": ["out/final_state.csv", "out/frames.pvd", "out/summary.json"]})");
  for (const char* name : {"final_state.csv", "frames.pvd", "frames/frame_000000.vtp", "frames/frame_000001.vtp"})
    put(dir, std::string("out/") + name, "old");
  EXPECT_THROW(OutputFolder(dir.path("out"), "run", {"final_state.csv"}, false), InputError);
  { OutputFolder folder(dir.path("out"), "run", {"final_state.csv"}, true); }
  EXPECT_EQ(files_in(dir.path("out")), (std::set<std::string>{"summary.json"}));

  // Its `stiffness` wrote no summary.json: stiffness.json, recognised by its keys, stands for the run.
  put(dir, "st/stiffness.json", R"({"scenario": "s.yaml", "method": "dsm", "stiffness_N_per_m": 1, "details": {}})");
  put(dir, "st/displacement.vtp", "old");
  put(dir, "st/notes.txt", "mine");
  const std::vector<std::string> outputs{"stiffness.json", "displacement.vtp", "stiffness_map.vtp"};
  EXPECT_THROW(OutputFolder(dir.path("st"), "stiffness", outputs, false), InputError);
  { OutputFolder folder(dir.path("st"), "stiffness", outputs, true); }
  EXPECT_EQ(files_in(dir.path("st")), (std::set<std::string>{"notes.txt", "summary.json"}));
}

TEST(OutputFolder, StatusLinesArriveThroughAPipeWhileTheRunGoesOn) {
  TempDir dir;
  // Some tenths of a second of stepping three particles, with no output until the end.
  std::string slow = test::edited("max_steps: 200", "max_steps: 200000");
  test::replace_once(slow, "every_steps: 50", "every_steps: 200000\n  vtk: false");
  dir.write("slow.yaml", slow);
  const std::string command = "cd '" + dir.path("") + "' && '" + BPMKIT_EXE + "' run slow.yaml --out out";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char line[4096];
  ASSERT_NE(std::fgets(line, sizeof line, pipe), nullptr);
  // With a block-buffered stdout the header would only arrive at the end, with "finished".
  EXPECT_NE(std::string(line).find("slow.yaml: 3 particles"), std::string::npos) << line;
  EXPECT_EQ(summary_of(dir.path("out"))["status"], "running");
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
  }
  const int status = ::pclose(pipe);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(summary_of(dir.path("out"))["status"], "finished");
}

}  // namespace
}  // namespace bpm
