#include "cli/stiffness_options.hpp"

#include <fmt/core.h>
#include <omp.h>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "io/log.hpp"
#include "solvers/mpi_world.hpp"

namespace bpm::cli {

void add_stiffness_options(CLI::App* cmd, StiffnessCliOptions& o, const std::string& default_out) {
  o.out_dir = default_out;
  cmd->add_option(
         "scenario", o.scenario,
         "scenario file (YAML) with a compression section: the structure, materials and platens")
      ->required();
  add_output_options(cmd, o.out_dir, o.overwrite);
  cmd->add_option("--dofs", o.dofs,
                  "DSM degrees of freedom per particle: 6, or 3 (translation only, Jarolin 3.1.1)")
      ->check(CLI::IsMember({3, 6}))
      ->capture_default_str();
  cmd->add_option("--solver", o.solver, "DSM linear solver: auto, cholmod, amg")
      ->capture_default_str();
  cmd->add_option("--tolerance", o.tolerance,
                  "DSM iterative solver: relative residual [default: 1e-6 (Jarolin), the DSM with "
                  "walls' tangent "
                  "solves and Newton's operating points 1e-3]");
  cmd->add_option(
         "--nonlinear-tolerance", o.nonlinear_tolerance,
         "nonlinear DSM: Newton stops at |residual| <= this |platen contact forces| at each step")
      ->capture_default_str();
  cmd->add_option("--slip", o.slip,
                  "dsm (with walls) and dsm-nonlinear: Coulomb slip at the contacts with the DEM's "
                  "history (on), or the paper's no slip (off)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_option("--axes", o.axes,
                  "dsm (with walls) and dsm-nonlinear: the bonds' normal forces along their "
                  "current axes with their current length, as in the DEM (current), or the "
                  "initial ones, the paper's small displacements (initial)")
      ->check(CLI::IsMember({"current", "initial"}))
      ->capture_default_str();
  cmd->add_option("--load-steps", o.load_steps,
                  "nonlinear DSM: equal steps of the platen travel along the loading path")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--window-points", o.window_points,
                  "dsm (with walls): tangents averaged over the fit window, the quadrature of the "
                  "DEM's least-squares "
                  "slope [default: 24 if a platen zone holds fewer than 50 particles, else 2]")
      ->check(CLI::Range(1, 32));
  cmd->add_option("--volumes", o.volumes, "STE particle volumes: voronoi or solid-fraction")
      ->capture_default_str();
  cmd->add_flag("--layered", o.layered,
                "STE: springs-in-series layers along the axis (varying cross-section)");
}

Scenario load_compression_scenario(const std::string& path, bool time_step) {
  ScenarioLoadOptions options;
  options.time_step = time_step;
  Scenario scenario = load_scenario(path, options);
  if (!scenario.compression) {
    throw InputError(path, "has no compression section, which defines the platens and the strain",
                     "add `compression: {platen_material: ..., strain_rate: ..., target_strain: "
                     "...}` (docs/scenario.md)");
  }
  if (scenario.compression->test != LabTest::uniaxial) {
    throw InputError(
        path + ": compression.test",
        "is " + std::string(to_string(scenario.compression->test)) +
            "; stiffness, calibrate and compare measure the uniaxial compression between platens",
        "run the strength test with `bpmkit run`, or set test: uniaxial");
  }
  return scenario;
}

StiffnessSettings make_stiffness_settings(const Scenario& scenario, const StiffnessCliOptions& o) {
  StiffnessSettings s;
  s.compression = *scenario.compression;
  // The stiffness needs the curve up to target_strain only: a UCS scenario's run past the peak
  // (failure_drop) is `bpmkit run`'s.
  s.compression.failure_drop = 0.0;
  s.compression.max_strain = 0.0;
  s.dsm.dofs = o.dofs;
  s.dsm.solver.kind = parse_sparse_solver(o.solver, "--solver");
  if (o.tolerance)
    s.dsm.solver.tolerance = s.dsm.tangent_tolerance = s.dsm.operating_point_tolerance =
        *o.tolerance;
  s.dsm.nonlinear_tolerance = o.nonlinear_tolerance;
  s.dsm.slip = o.slip == "on";
  s.dsm.bond_axes = o.axes == "current";
  s.dsm.load_steps = o.load_steps;
  if (o.window_points) s.dsm.window_points = *o.window_points;
  s.ste.volumes = ste::parse_volume_method(o.volumes, "--volumes");
  s.ste.layered = o.layered;
  return s;
}

void log_settings(const StiffnessCliOptions& o) {
  log::detail(
      "settings: DSM {} DOF per particle, solver {}, tolerance {}, nonlinear tolerance {:g}; STE "
      "volumes {}{}; "
      "{} OpenMP threads\n",
      o.dofs, o.solver, o.tolerance ? fmt::format("{:g}", *o.tolerance) : std::string("default"),
      o.nonlinear_tolerance, o.volumes, o.layered ? ", layered" : "", omp_get_max_threads());
}

void print_estimate(const StiffnessEstimate& e) {
  const std::string body = e.body.valid
                               ? fmt::format("   body (middle third): E = {:.6g} Pa, nu = {:.4f}",
                                             e.body.youngs_modulus, e.body.poissons_ratio)
                               : std::string();
  fmt::print("{:<14} K = {:.6g} N/m   K l / A = {:.6g} Pa{}   {:.3f} s\n", to_string(e.method),
             e.stiffness, e.youngs_modulus, body, e.seconds);
}

void require_methods_across_ranks(const std::vector<StiffnessMethod>& methods,
                                  const std::string& where) {
  if (!mpi::world().distributed()) return;
  for (const StiffnessMethod m : methods) {
    if (m == StiffnessMethod::dsm || m == StiffnessMethod::dsm_nonlinear ||
        m == StiffnessMethod::ste)
      continue;
    throw InputError(where + " " + std::string(to_string(m)), "does not run across MPI ranks",
                     "run it without mpirun; under mpirun: dsm, dsm-nonlinear (K divided between "
                     "the ranks) and ste");
  }
}

}  // namespace bpm::cli
