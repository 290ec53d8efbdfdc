#pragma once
/// Each subcommand registers itself on the application; main() only dispatches and reports errors.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace bpm::cli {

void add_run_command(CLI::App& app);
void add_verify_command(CLI::App& app);
void add_generate_command(CLI::App& app);
void add_stiffness_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_compare_command(CLI::App& app);

struct CantileverSuiteOptions {
  std::string json_path = "out/cantilever/cantilever.json";  ///< summary JSON
  std::string csv_dir = "out/cantilever";                    ///< CSV tables
  std::vector<int> cases = {1, 2, 3, 4, 5};
};
/// Runs Chen's cases, prints the table, writes JSON and CSV; returns the number of failed checks.
int run_cantilever_suite(const CantileverSuiteOptions& options);

}  // namespace bpm::cli
