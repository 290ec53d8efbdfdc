// `bpmkit run SCENARIO.yaml --out DIR`: loads a scenario (docs/scenario.md), runs it to its stop
// criterion and writes the final state, probe time series, VTK frames and a JSON summary.
#include <fmt/core.h>

#include <omp.h>

#include <filesystem>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "cli/dem_progress.hpp"
#include "core/error.hpp"
#include "scenario/checkpoint.hpp"
#include "io/log.hpp"
#include "io/output_folder.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_run.hpp"
#include "io/stop_signal.hpp"

namespace bpm::cli {
namespace {

struct RunOptions {
  std::string scenario;
  std::string out_dir = "out/run";
  bool overwrite = false;
  std::string resume_dir;  ///< --resume: continue the run in this folder from its checkpoint
  bool out_given = false;
};

/// The folder to write: a fresh one, or with --resume the interrupted run's, which is kept.
OutputFolder claim_folder(const RunOptions& options, const Scenario& scenario) {
  if (options.resume_dir.empty()) return OutputFolder(options.out_dir, "run", scenario_outputs(scenario), options.overwrite);
  if (options.overwrite) {
    throw InputError("--resume", "cannot be combined with --overwrite", "--resume continues a run, --overwrite starts afresh: give one");
  }
  if (options.out_given && options.out_dir != options.resume_dir) {
    throw InputError("--resume", "continues the run in its own folder; --out names another",
                     "drop --out: the resumed run writes into " + options.resume_dir);
  }
  // Refusals first (a foreign or damaged checkpoint), so that they leave the folder as it was.
  return OutputFolder::resume(options.resume_dir, "run", scenario_outputs(scenario), [&] {
    check_checkpoint((std::filesystem::path(options.resume_dir) / kCheckpointFile).string(), scenario);
  });
}

void run(const RunOptions& options) {
  Scenario scenario = load_scenario(options.scenario);
  OutputFolder folder = claim_folder(options, scenario);
  const std::string& out_dir = folder.dir();
  log::info("{}: {} particles, {} bonds, time step {:.4g} s (stability limit {:.4g} s)\n", options.scenario,
            scenario.model.particles.size(), scenario.model.bonds.size(), scenario.time_step,
            scenario.time_step_limit);
  const ProgressPlan plan = progress_plan(scenario);
  log::detail("time step: {}; {:.4g} steps to t = {:.6g} s; {} OpenMP threads\n",
              scenario.time_step == scenario.safety_factor * scenario.time_step_limit
                  ? fmt::format("safety factor {} x the bonds' and contacts' stability limit", scenario.safety_factor)
                  : std::string("integrator.time_step as given"),
              plan.end_time / scenario.time_step, plan.end_time, omp_get_max_threads());
  const ScenarioRunResult result = [&] {
    const DemProgress progress(plan);
    // Ctrl-C and SIGTERM end the run cleanly with a checkpoint (io/stop_signal.hpp).
    install_stop_signal_handlers();
    ScenarioRunOptions run_options;
    run_options.resume = !options.resume_dir.empty();
    return run_scenario(scenario, folder, run_options);
  }();
  if (result.resumed_from_step >= 0) log::info("resumed from the checkpoint at step {}\n", result.resumed_from_step);
  const RunSummary& s = result.summary;
  if (result.compression) {
    const CompressionResult& c = *result.compression;
    fmt::print("{} test to strain {:.4g} ({}) in {} steps{}, wall {:.2f} s\n", to_string(c.test), c.curve.back().strain, c.stop,
               s.steps, c.mass_scaling != 1.0 ? fmt::format(" (masses x {:g})", c.mass_scaling) : "", s.wall_seconds);
  }
  if (result.compression && result.compression->stop == "interrupted") {
    // No fit, no strength yet: the curve so far is in force_displacement.csv.
    fmt::print("peak stress so far {:.6g} Pa; K, E and the strength are computed when the test ends\n",
               result.compression->peak_stress);
  } else if (result.compression) {
    const CompressionResult& c = *result.compression;
    fmt::print("sample l = {:.6g} m, A = {:.6g} m^2; stiffness K = {:.6g} N/m (fit r^2 = {:.6f}), E = K l / A = {:.6g} Pa\n",
               c.sample.length, c.sample.area, c.stiffness, c.fit_r2, c.youngs_modulus);
    if (c.body.valid) {
      fmt::print("body (strain gauges on the middle third, {} particles): E = {:.6g} Pa, nu = {:.4f}\n",
                 c.gauge_particles, c.body.youngs_modulus, c.body.poissons_ratio);
    }
    fmt::print("quasi-static check: kinetic/elastic energy <= {:.3g}, platen force imbalance <= {:.3g}; peak stress {:.6g} Pa\n",
               c.max_kinetic_ratio, c.max_force_imbalance, c.peak_stress);
    const std::size_t broken = c.curve.empty() ? 0 : c.curve.back().bonds_broken;
    const std::size_t tensile = c.curve.empty() ? 0 : c.curve.back().bonds_broken_tension;
    fmt::print("{} test: {} = {:.6g} Pa at peak force {:.6g} N, strain {:.4g} (kinetic/elastic {:.3g}, force "
               "imbalance {:.3g} there); bonds broken: {} in tension, {} in shear\n",
               to_string(c.test), strength_definition(c.test), c.strength, c.peak_force, c.peak_strain, c.peak_kinetic_ratio, c.peak_force_imbalance, tensile,
               broken - tensile);
  } else {
    fmt::print("stopped by {} after {} steps, t = {:.6g} s, wall {:.2f} s, {:.3g} bond updates/s\n",
               to_string(s.reason), s.steps, s.time, s.wall_seconds, s.bond_updates_per_second);
  }
  log::info("wrote {} files to {} (summary.json lists them)\n", result.files.size(), out_dir);
  if (result.status == "interrupted") {
    const int signal = stop_signal_received();
    fmt::print("interrupted at step {}, t = {:.6g} s; checkpoint written; continue with: bpmkit run {} --resume {}\n",
               s.steps, s.time, options.scenario, out_dir);
    throw CLI::RuntimeError(signal > 0 ? 128 + signal : 1);  // the shell's status for death by that signal
  }
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "run a scenario file (YAML; see docs/scenario.md)");
  auto options = std::make_shared<RunOptions>();
  cmd->add_option("scenario", options->scenario, "scenario file (YAML)")->required();
  add_output_options(cmd, options->out_dir, options->overwrite);
  cmd->add_option("--resume", options->resume_dir,
                  "continue the interrupted run in this folder from its checkpoint.bin (same scenario; the tables "
                  "there are continued)");
  cmd->callback([options, cmd] {
    options->out_given = cmd->count("--out") > 0;
    run(*options);
  });
}

}  // namespace bpm::cli
