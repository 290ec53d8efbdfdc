#pragma once
/// Runs a loaded scenario and writes its results: what `bpmkit run` does, as a library function so
/// that tests and other front ends can do the same.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dem/simulation.hpp"
#include "io/output_folder.hpp"
#include "scenario/scenario.hpp"

namespace bpm {

struct ScenarioRunResult {
  RunSummary summary;
  Energies energies;               ///< at the end
  std::vector<std::string> files;  ///< every file written, in order
  std::size_t frames = 0;          ///< output times (probe rows; VTK frames if enabled)
  std::optional<CompressionResult> compression;  ///< for a scenario with a compression section
  std::string status = "finished";  ///< or "interrupted" (a checkpoint was written)
  std::int64_t resumed_from_step = -1;  ///< the checkpoint's step when resumed, -1 otherwise
};

struct ScenarioRunOptions {
  /// Continue from the folder's checkpoint.bin (scenario/checkpoint.hpp) instead of starting; the tables
  /// there are continued. The folder must be claimed with OutputFolder::resume.
  bool resume = false;
  /// Checked after each step besides SIGINT/SIGTERM (io/stop_signal.hpp): true interrupts the run
  /// as a signal would (tests stop a run at a chosen step this way).
  std::function<bool(const Simulation&)> interrupt_when;
};

/// Simulates `scenario` (its model advances in place) until a stop criterion holds and writes into
/// out_dir (created if needed):
///   final_state.csv                  every particle at the end (see state_csv.hpp)
///   probes.csv                       probe time series, if the scenario has probes
///   frames/frame_NNNNNN.vtp, frames.pvd   VTK frames and their collection, if output.vtk
///   walls.csv                        wall displacements and forces, if there are walls
///   bond_breaks.csv                  broken bonds, if any bond has a strength
///   force_displacement.csv           the curve of a compression test
///   summary.json                     run summary (see summary_json.hpp)
///   checkpoint.bin                   the state to resume from, while the run is unfinished
/// Outputs are taken at t = 0, every output.every_steps steps, and at the end. The folder is
/// claimed first (io/output_folder.hpp; an earlier run's folder is refused).
ScenarioRunResult run_scenario(Scenario& scenario, const std::string& out_dir);

/// The same into a folder claimed by the caller for scenario_outputs(scenario) (`bpmkit run`
/// claims it before printing its first line).
///
/// The tables and frames.pvd are written as the run goes (scenario/run_outputs.hpp). A run writes
/// checkpoint.bin every output.checkpoint_every and when interrupted (SIGINT, SIGTERM,
/// options.interrupt_when: status "interrupted", no final output, no final_state.csv); a plain run
/// (no compression section) also when it diverges (the state as it is then, with final_state.csv;
/// status "diverged", the DivergenceError is thrown on), while a diverging compression test
/// removes its checkpoint; a run that finishes removes it. A compression test resumes too.
ScenarioRunResult run_scenario(Scenario& scenario, OutputFolder& folder, const ScenarioRunOptions& options = {});

/// The names of the files above that `scenario` may write, for OutputFolder.
std::vector<std::string> scenario_outputs(const Scenario& scenario);

}  // namespace bpm
