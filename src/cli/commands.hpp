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
void add_plot_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_export_command(CLI::App& app);

/// --out DIR and --overwrite, the same for every command that writes a folder
/// (io/output_folder.hpp: an output folder is one run).
inline void add_output_options(CLI::App* cmd, std::string& out_dir, bool& overwrite) {
  cmd->add_option("--out", out_dir, "output folder; one run each: a folder holding an earlier run is refused")
      ->capture_default_str();
  cmd->add_flag("--overwrite", overwrite,
                "replace the earlier run in --out: delete the files its summary.json lists first (no other file)");
}

struct CantileverSuiteOptions {
  std::string out_dir = "out/cantilever";  ///< cantilever.json and the CSV tables
  bool overwrite = false;
  std::vector<int> cases = {1, 2, 3, 4, 5};
};
/// Runs Chen's cases, prints the table, writes JSON and CSV; returns the number of failed checks.
int run_cantilever_suite(const CantileverSuiteOptions& options);

}  // namespace bpm::cli
