#pragma once
/// Runs a loaded scenario and writes its results: what `bpmkit run` does, as a library function so
/// that tests and other front ends can do the same.
#include <optional>
#include <string>
#include <vector>

#include "dem/simulation.hpp"
#include "io/output_folder.hpp"
#include "io/scenario.hpp"

namespace bpm {

struct ScenarioRunResult {
  RunSummary summary;
  Energies energies;               ///< at the end
  std::vector<std::string> files;  ///< every file written, in order
  std::size_t frames = 0;          ///< output times (probe rows; VTK frames if enabled)
  std::optional<CompressionResult> compression;  ///< for a scenario with a compression section
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
/// Outputs are taken at t = 0, every output.every_steps steps, and at the end. The folder is
/// claimed first (io/output_folder.hpp; an earlier run's folder is refused).
ScenarioRunResult run_scenario(Scenario& scenario, const std::string& out_dir);

/// The same into a folder claimed by the caller for scenario_outputs(scenario) (`bpmkit run`
/// claims it before printing its first line).
ScenarioRunResult run_scenario(Scenario& scenario, OutputFolder& folder);

/// The names of the files above that `scenario` may write, for OutputFolder.
std::vector<std::string> scenario_outputs(const Scenario& scenario);

}  // namespace bpm
