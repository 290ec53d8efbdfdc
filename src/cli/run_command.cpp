// `bpmkit run SCENARIO.yaml --out DIR`: loads a scenario (docs/scenario.md), runs it to its stop
// criterion and writes the final state, probe time series, VTK frames and a JSON summary.
#include <fmt/core.h>

#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "io/scenario.hpp"
#include "io/scenario_run.hpp"

namespace bpm::cli {
namespace {

struct RunOptions {
  std::string scenario;
  std::string out_dir = "out/run";
};

void run(const RunOptions& options) {
  Scenario scenario = load_scenario(options.scenario);
  fmt::print("{}: {} particles, {} bonds, time step {:.4g} s (stability limit {:.4g} s)\n", options.scenario,
             scenario.model.particles.size(), scenario.model.bonds.size(), scenario.time_step,
             scenario.time_step_limit);
  const ScenarioRunResult result = run_scenario(scenario, options.out_dir);
  const RunSummary& s = result.summary;
  fmt::print("stopped by {} after {} steps, t = {:.6g} s, wall {:.2f} s, {:.3g} bond updates/s\n",
             to_string(s.reason), s.steps, s.time, s.wall_seconds, s.bond_updates_per_second);
  fmt::print("wrote {} files to {} (summary.json lists them)\n", result.files.size(), options.out_dir);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "run a scenario file (YAML; see docs/scenario.md)");
  auto options = std::make_shared<RunOptions>();
  cmd->add_option("scenario", options->scenario, "scenario file (YAML)")->required();
  cmd->add_option("--out", options->out_dir, "output directory")->capture_default_str();
  cmd->callback([options] { run(*options); });
}

}  // namespace bpm::cli
