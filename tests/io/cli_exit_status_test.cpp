// The bpmkit command's exit status: usage errors (unknown option, missing argument, bad
// subcommand) and input errors exit 2; --help and --version exit 0; no arguments prints the help
// and exits 0 without running anything.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bpmkit_process.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::Outcome;
using test::run_bpmkit;
using test::TempDir;

TEST(CliExitStatus, NoArgumentsPrintsTheHelpAndRunsNothing) {
  TempDir dir;
  const Outcome o = run_bpmkit("", dir.path(""));
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("Subcommands:"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("verify"), std::string::npos) << o.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path("out")))
      << "bpmkit with no arguments wrote results";
}

TEST(CliExitStatus, UsageErrorsExitTwo) {
  TempDir dir;
  for (const std::string args : {"--no-such-option", "frobnicate", "run", "run scenario.yaml --out",
                                 "verify", "verify cantilever --cases 9", "run a.yaml b.yaml"}) {
    const Outcome o = run_bpmkit(args, dir.path(""));
    EXPECT_EQ(o.status, 2) << "bpmkit " << args << ":\n" << o.output;
    EXPECT_FALSE(o.output.empty()) << "bpmkit " << args << " printed no message";
  }
}

TEST(CliExitStatus, HelpAndVersionExitZero) {
  TempDir dir;
  for (const std::string args : {"--help", "--version", "run --help", "verify cantilever --help"}) {
    const Outcome o = run_bpmkit(args, dir.path(""));
    EXPECT_EQ(o.status, 0) << "bpmkit " << args << ":\n" << o.output;
  }
}

TEST(CliExitStatus, InputErrorsExitTwoAndNameTheFile) {
  TempDir dir;
  Outcome o = run_bpmkit("run no_such.yaml", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("no_such.yaml"), std::string::npos) << o.output;
  // The reproduction of issue 11: an unclosed quote swallowed the output section and the run
  // exited 0.
  std::string yaml = test::edited("output:\n", "description: \"three particles\noutput:\n");
  dir.write("scenario.yaml", yaml);
  o = run_bpmkit("run scenario.yaml --out out/run", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("scenario.yaml:" + std::to_string(test::line_of(yaml, "description:"))),
            std::string::npos)
      << o.output;
}

}  // namespace
}  // namespace bpm
