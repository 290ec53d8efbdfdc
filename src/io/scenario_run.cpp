#include "io/scenario_run.hpp"

#include <fmt/core.h>

#include <optional>

#include "io/probe_recorder.hpp"
#include "io/result_tables.hpp"
#include "io/state_csv.hpp"
#include "io/summary_json.hpp"
#include "io/vtk_writer.hpp"

namespace bpm {
namespace {
nlohmann::json run_into(Scenario& scenario, const OutputFolder& folder, ScenarioRunResult& result) {
  auto write = [&](const std::string& relative, std::string_view content) {
    result.files.push_back(folder.write(relative, content));
    return result.files.back();
  };

  const Model& model = scenario.model;
  ProbeRecorder probes(scenario.probes);
  std::string walls_csv;
  std::vector<VtkFrame> frames;
  std::int64_t last_output_step = -1;
  auto output = [&](const Simulation& sim) {
    // run() calls the observer once more at the end, which may be the step just written.
    if (sim.steps() == last_output_step) return;
    last_output_step = sim.steps();
    ++result.frames;
    if (!scenario.probes.empty()) probes.record(sim.time(), model.particles);
    if (!model.walls.empty()) walls_csv += walls_row(model.walls, sim.time(), walls_csv.empty());
    if (scenario.output.vtk) {
      const std::string file = fmt::format("frames/frame_{:06d}.vtp", frames.size());
      write(file, polydata_vtp(model));
      frames.push_back({sim.time(), file});
    }
  };

  std::optional<CompressionResult>& compression = result.compression;
  if (scenario.compression) {
    // The test sets its own output times: the points of its force-displacement curve.
    compression = run_uniaxial_compression(scenario.model, *scenario.compression,
                                           [&](const Simulation& sim, const CompressionPoint&) { output(sim); });
    result.summary = compression->run;
    result.energies = compression->final_energies;
  } else {
    Simulation sim(scenario.model, scenario.time_step);
    output(sim);  // the initial state (loads evaluated at t = 0)
    result.summary = sim.run(scenario.stop, output, scenario.output.every_steps);
    result.energies = sim.energies();
  }

  // The summary lists these result files but only counts the frames (a long run has thousands).
  std::vector<std::string> outputs{write("final_state.csv", state_csv(model.particles))};
  if (!scenario.probes.empty()) outputs.push_back(write("probes.csv", probes.csv()));
  if (!walls_csv.empty()) outputs.push_back(write("walls.csv", walls_csv));
  if (model.bonds.breakable) outputs.push_back(write("bond_breaks.csv", bond_breaks_csv(model, scenario.time_step)));
  if (compression) outputs.push_back(write("force_displacement.csv", force_displacement_csv(*compression)));
  if (scenario.output.vtk) outputs.push_back(write("frames.pvd", collection_pvd(frames)));
  outputs.push_back(folder.path("summary.json"));
  result.files.push_back(outputs.back());  // written by OutputFolder::run
  nlohmann::json summary = summary_json(scenario, result.summary, result.energies);
  if (compression) {
    summary["stop_reason"] = compression->stop;
    summary["compression"] = compression_json(*compression);
  }
  summary["outputs"] = outputs;
  summary["output_times"] = result.frames;
  summary["vtk_frames"] = frames.size();
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
  return names;
}

ScenarioRunResult run_scenario(Scenario& scenario, const std::string& out_dir) {
  OutputFolder folder(out_dir, "run", scenario_outputs(scenario), false);
  return run_scenario(scenario, folder);
}

ScenarioRunResult run_scenario(Scenario& scenario, OutputFolder& folder) {
  ScenarioRunResult result;
  folder.run([&] { return run_into(scenario, folder, result); });
  return result;
}

}  // namespace bpm
