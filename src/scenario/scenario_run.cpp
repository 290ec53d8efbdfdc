#include "scenario/scenario_run.hpp"

#include <filesystem>
#include <optional>
#include <system_error>

#include "core/error.hpp"
#include "scenario/checkpoint.hpp"
#include "io/result_tables.hpp"
#include "scenario/run_outputs.hpp"
#include "io/state_csv.hpp"
#include "io/stop_signal.hpp"
#include "scenario/summary_json.hpp"

namespace bpm {
namespace {

/// SIGINT or SIGTERM since the handlers were installed (io/stop_signal.hpp), or the caller's test.
bool interrupted(const ScenarioRunOptions& options, const Simulation& sim) {
  return stop_signal_received() != 0 || (options.interrupt_when && options.interrupt_when(sim));
}

/// Removes the folder's checkpoint (and a .tmp left by a kill while one was written).
void remove_checkpoint(const OutputFolder& folder) {
  std::error_code ec;
  std::filesystem::remove(folder.path(kCheckpointFile), ec);
  std::filesystem::remove(folder.path(std::string(kCheckpointFile) + ".tmp"), ec);
}

/// The compression test, started or resumed, with its checkpoints: it sets its own output times
/// (the points of its force-displacement curve). Returns the path of the checkpoint it wrote last
/// ("" if none).
std::string run_compression(Scenario& scenario, const OutputFolder& folder,
                            const ScenarioRunOptions& options, RunOutputs& outputs,
                            ScenarioRunResult& result) {
  // From the model as loaded, before the test adds its platens and scales the masses: the same
  // identity at the start and at a resume.
  const CheckpointIdentity identity = checkpoint_identity(scenario, scenario.time_step);
  const double area = compression_sample(scenario.model, *scenario.compression).area;
  std::string checkpoint;
  bool stopping = false;
  CompressionHooks hooks;
  hooks.checkpoint_every = scenario.output.checkpoint_every_steps;
  hooks.checkpoint = [&](const Simulation& sim, const CompressionProgress& progress) {
    const CheckpointKind kind = stopping ? CheckpointKind::interrupted : CheckpointKind::periodic;
    checkpoint = folder.write(kCheckpointFile,
                              checkpoint_bytes(identity, sim, kind, outputs.progress(), &progress));
  };
  hooks.interrupted = [&](const Simulation& sim) {
    stopping = interrupted(options, sim);
    return stopping;
  };
  if (options.resume) {
    hooks.resume = [&](Simulation& sim, CompressionProgress& progress) {
      outputs.resume(
          restore_checkpoint(folder.path(kCheckpointFile), identity, scenario, sim, &progress));
      result.resumed_from_step = sim.steps();
    };
  } else {
    outputs.start();
  }
  try {
    result.compression = run_uniaxial_compression(
        scenario.model, *scenario.compression,
        [&](const Simulation& sim, const CompressionPoint& point) {
          outputs.output(sim);
          outputs.curve_point(point, area);
        },
        hooks);
  } catch (const DivergenceError&) {
    // The last periodic checkpoint would only diverge again: nothing to resume.
    remove_checkpoint(folder);
    throw;
  }
  result.summary = result.compression->run;
  result.energies = result.compression->final_energies;
  if (result.compression->stop == "interrupted") result.status = "interrupted";
  return checkpoint;
}

/// A plain run, started or resumed, with its checkpoints; returns the path of the checkpoint it
/// wrote last ("" if none). A divergence writes the state as it is (keeping the last good one
/// would cost a copy every step) and is thrown on.
std::string run_plain(Scenario& scenario, const OutputFolder& folder, const ScenarioRunOptions& options,
                      RunOutputs& outputs, ScenarioRunResult& result) {
  Simulation sim(scenario.model, scenario.time_step);
  const CheckpointIdentity identity = checkpoint_identity(scenario, sim.dt());
  std::string checkpoint;
  auto write_checkpoint = [&](const Simulation& s, CheckpointKind kind) {
    checkpoint = folder.write(kCheckpointFile, checkpoint_bytes(identity, s, kind, outputs.progress()));
  };
  if (options.resume) {
    outputs.resume(restore_checkpoint(folder.path(kCheckpointFile), identity, scenario, sim));
    result.resumed_from_step = sim.steps();
  } else {
    outputs.start();
    outputs.output(sim);  // the initial state (loads evaluated at t = 0)
  }
  bool stopping = false;
  RunHooks hooks;
  hooks.checkpoint_every = scenario.output.checkpoint_every_steps;
  hooks.checkpoint = [&](const Simulation& s) {
    write_checkpoint(s, stopping ? CheckpointKind::interrupted : CheckpointKind::periodic);
  };
  hooks.interrupted = [&](const Simulation& s) {
    stopping = interrupted(options, s);
    return stopping;
  };
  try {
    result.summary = sim.run(scenario.stop, [&](const Simulation& s) { outputs.output(s); },
                             scenario.output.every_steps, hooks);
  } catch (const DivergenceError&) {
    outputs.finish(scenario.model, sim.dt());
    write_checkpoint(sim, CheckpointKind::diverged);
    folder.write("final_state.csv", state_csv(scenario.model.particles));
    throw;
  }
  result.energies = sim.energies();
  if (result.summary.reason == StopReason::interrupted) result.status = "interrupted";
  return checkpoint;
}

nlohmann::json run_into(Scenario& scenario, const OutputFolder& folder, const ScenarioRunOptions& options,
                        ScenarioRunResult& result) {
  const Model& model = scenario.model;
  RunOutputs outputs(scenario, folder, result.files);
  const std::optional<CompressionResult>& compression = result.compression;
  std::string checkpoint;  // its path, when this run leaves one
  if (scenario.compression) {
    checkpoint = run_compression(scenario, folder, options, outputs, result);
  } else {
    checkpoint = run_plain(scenario, folder, options, outputs, result);
  }
  outputs.finish(model, scenario.time_step);
  result.frames = outputs.output_times();

  // The summary lists these result files but only counts the frames (a long run has thousands).
  std::vector<std::string> files;
  if (result.status == "finished") files.push_back(folder.write("final_state.csv", state_csv(model.particles)));
  for (const std::string& table : outputs.table_paths()) files.push_back(table);
  if (scenario.output.vtk) files.push_back(folder.path("frames.pvd"));
  if (result.status == "finished") {
    remove_checkpoint(folder);  // nothing to resume (a stale .tmp included)
    checkpoint.clear();
  }
  if (!checkpoint.empty()) files.push_back(checkpoint);
  result.files.insert(result.files.end(), files.begin(), files.end());
  files.push_back(folder.path("summary.json"));
  result.files.push_back(files.back());  // written by OutputFolder::run
  nlohmann::json summary = summary_json(scenario, result.summary, result.energies);
  if (compression) {
    summary["stop_reason"] = compression->stop;
    summary["compression"] = compression_json(*compression);
  }
  summary["outputs"] = files;
  summary["output_times"] = result.frames;
  summary["vtk_frames"] = outputs.frames();
  if (result.resumed_from_step >= 0) summary["resumed_from_step"] = result.resumed_from_step;
  if (result.status != "finished") {
    summary["status"] = result.status;
    summary["checkpoint"] = checkpoint.empty() ? nlohmann::json(nullptr) : nlohmann::json(checkpoint);
  }
  return summary;
}
}  // namespace

std::vector<std::string> scenario_outputs(const Scenario& scenario) {
  const Model& model = scenario.model;
  std::vector<std::string> names{"final_state.csv"};
  if (!scenario.probes.empty()) names.push_back("probes.csv");
  if (!model.walls.empty() || scenario.compression) names.push_back("walls.csv");  // the test adds platens
  if (model.bonds.breakable) names.push_back("bond_breaks.csv");
  if (scenario.compression) names.push_back("force_displacement.csv");
  if (scenario.output.vtk) {
    names.push_back("frames.pvd");
    names.push_back("frames/frame_*.vtp");
  }
  if (has_wall_frames(scenario)) names.push_back(kWallFrames);
  if (scenario.output.bond_csv) names.push_back("bonds/bonds_*.csv");
  names.push_back(kCheckpointFile);
  return names;
}

ScenarioRunResult run_scenario(Scenario& scenario, const std::string& out_dir) {
  OutputFolder folder(out_dir, "run", scenario_outputs(scenario), false);
  return run_scenario(scenario, folder);
}

ScenarioRunResult run_scenario(Scenario& scenario, OutputFolder& folder, const ScenarioRunOptions& options) {
  ScenarioRunResult result;
  folder.run([&] { return run_into(scenario, folder, options, result); });
  return result;
}

}  // namespace bpm
