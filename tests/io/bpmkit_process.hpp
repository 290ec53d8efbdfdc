#pragma once
// Runs the bpmkit executable (BPMKIT_EXE, set by tests/io/CMakeLists.txt) through the shell, for
// the tests of what the command does: exit status, messages, output folders.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace bpm::test {

struct Outcome {
  int status = -1;
  std::string output;  ///< stdout and stderr
};

/// Runs `bpmkit ARGS` in the folder `cwd`.
inline Outcome run_bpmkit(const std::string& args, const std::string& cwd) {
  const std::string command = "cd '" + cwd + "' && '" + BPMKIT_EXE + "' " + args + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "cannot run " << command;
    return {};
  }
  Outcome o;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    o.output.append(buffer, n);
  const int wait_status = ::pclose(pipe);
  o.status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
  return o;
}

}  // namespace bpm::test
