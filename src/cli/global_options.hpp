#pragma once
/// The options every command shares, given before or after the subcommand:
///   --threads N   OpenMP threads (default: OMP_NUM_THREADS, else every core)
///   --quiet       only errors, warnings and the result lines (no progress line)
///   --verbose     also the details (time step choice, neighbour list builds)
/// They take effect while the command line is parsed, before any command's work.
#include <CLI/CLI.hpp>

namespace bpm::cli {

void add_global_options(CLI::App& app);

/// Whether the progress line of a DEM run is shown (not under --quiet).
bool progress_enabled();

}  // namespace bpm::cli
