// `bpmkit run SCENARIO.yaml --out DIR`: loads a scenario (docs/scenario.md), runs it to its stop
// criterion and writes the final state, probe time series, VTK frames and a JSON summary.
#include <fmt/core.h>

#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "io/output_folder.hpp"
#include "io/scenario.hpp"
#include "io/scenario_run.hpp"

namespace bpm::cli {
namespace {

struct RunOptions {
  std::string scenario;
  std::string out_dir = "out/run";
  bool overwrite = false;
};

void run(const RunOptions& options) {
  Scenario scenario = load_scenario(options.scenario);
  OutputFolder folder(options.out_dir, "run", scenario_outputs(scenario), options.overwrite);
  fmt::print("{}: {} particles, {} bonds, time step {:.4g} s (stability limit {:.4g} s)\n", options.scenario,
             scenario.model.particles.size(), scenario.model.bonds.size(), scenario.time_step,
             scenario.time_step_limit);
  const ScenarioRunResult result = run_scenario(scenario, folder);
  const RunSummary& s = result.summary;
  if (result.compression) {
    const CompressionResult& c = *result.compression;
    fmt::print("uniaxial compression to strain {:.4g} ({}) in {} steps, wall {:.2f} s\n", c.curve.back().strain, c.stop,
               s.steps, s.wall_seconds);
    fmt::print("sample l = {:.6g} m, A = {:.6g} m^2; stiffness K = {:.6g} N/m (fit r^2 = {:.6f}), E = K l / A = {:.6g} Pa\n",
               c.sample.length, c.sample.area, c.stiffness, c.fit_r2, c.youngs_modulus);
    fmt::print("quasi-static check: kinetic/elastic energy <= {:.3g}, platen force imbalance <= {:.3g}; peak stress {:.6g} Pa\n",
               c.max_kinetic_ratio, c.max_force_imbalance, c.peak_stress);
  } else {
    fmt::print("stopped by {} after {} steps, t = {:.6g} s, wall {:.2f} s, {:.3g} bond updates/s\n",
               to_string(s.reason), s.steps, s.time, s.wall_seconds, s.bond_updates_per_second);
  }
  fmt::print("wrote {} files to {} (summary.json lists them)\n", result.files.size(), options.out_dir);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "run a scenario file (YAML; see docs/scenario.md)");
  auto options = std::make_shared<RunOptions>();
  cmd->add_option("scenario", options->scenario, "scenario file (YAML)")->required();
  add_output_options(cmd, options->out_dir, options->overwrite);
  cmd->callback([options] { run(*options); });
}

}  // namespace bpm::cli
