#pragma once
/// The `bpmkit` command line as an object: the program (cli/main.cpp) and the Python module
/// (python/) build the same application, so a command run from Python is the command.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace bpm::cli {

/// Registers the version flag, the global options and every subcommand on `app`.
void add_commands(CLI::App& app);

/// Runs one command line in this process (args without the program name, e.g. {"stiffness",
/// "--method", "dsm", "s.yaml", "--out", "DIR"}). The command's exceptions pass through:
/// bpm::InputError for bad input, CLI::ParseError for a bad command line, CLI::RuntimeError for a
/// command that reports failure by its exit status.
void run_in_process(const std::vector<std::string>& args);

}  // namespace bpm::cli
