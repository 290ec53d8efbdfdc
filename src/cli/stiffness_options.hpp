#pragma once
/// What `bpmkit stiffness`, `calibrate` and `compare` share: the scenario (a YAML file with a
/// `compression` section: structure, materials, platens, target strain) and the method options.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "calibrate/stiffness_methods.hpp"
#include "scenario/scenario.hpp"

namespace bpm::cli {

struct StiffnessCliOptions {
  std::string scenario;
  std::string out_dir;
  bool overwrite = false;
  int dofs = 6;
  std::string solver = "auto";
  std::optional<double> tolerance;  ///< unset: each DSM's own default (DsmOptions)
  double nonlinear_tolerance = 1e-5;
  std::optional<int> window_points;  ///< unset: DsmOptions' default
  std::string slip =
      "on";  ///< dsm, dsm-nonlinear: Coulomb slip at the contacts (off: the paper's no slip)
  std::string axes = "current";  ///< dsm, dsm-nonlinear: bonds' normal forces on the current axes
  int load_steps = 10;           ///< dsm-nonlinear: equal steps of the platen travel
  std::string volumes = "solid-fraction";
  bool layered = false;
};

/// Registers the scenario argument, --out, --overwrite and the method options on `cmd`.
void add_stiffness_options(CLI::App* cmd, StiffnessCliOptions& options,
                           const std::string& default_out);

/// Loads the scenario; InputError if it has no compression section.
/// time_step: whether a method integrates in time (the DEM ones): ScenarioLoadOptions.
Scenario load_compression_scenario(const std::string& path, bool time_step = true);

StiffnessSettings make_stiffness_settings(const Scenario& scenario,
                                          const StiffnessCliOptions& options);

/// The method settings in one line (--verbose).
void log_settings(const StiffnessCliOptions& options);

/// Under mpirun (solvers/mpi_world.hpp) only dsm, dsm-nonlinear and ste are divided between the
/// ranks: throws InputError naming `where` if any of `methods` is another; does nothing without
/// mpirun.
void require_methods_across_ranks(const std::vector<StiffnessMethod>& methods,
                                  const std::string& where);

/// One line: method, K, E, wall time.
void print_estimate(const StiffnessEstimate& e);

}  // namespace bpm::cli
