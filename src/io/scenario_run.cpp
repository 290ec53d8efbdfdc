#include "io/scenario_run.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <optional>

#include "io/atomic_file.hpp"
#include "io/probe_recorder.hpp"
#include "io/result_tables.hpp"
#include "io/state_csv.hpp"
#include "io/summary_json.hpp"
#include "io/vtk_writer.hpp"

namespace bpm {
ScenarioRunResult run_scenario(Scenario& scenario, const std::string& out_dir) {
  const std::filesystem::path dir(out_dir);
  ScenarioRunResult result;
  auto write = [&](const std::string& relative, std::string_view content) {
    const std::string path = (dir / relative).string();
    write_file_atomic(path, content);
    result.files.push_back(path);
    return path;
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
  outputs.push_back((dir / "summary.json").string());
  nlohmann::json summary = summary_json(scenario, result.summary, result.energies);
  if (compression) {
    summary["stop_reason"] = compression->stop;
    summary["compression"] = compression_json(*compression);
  }
  summary["outputs"] = outputs;
  summary["output_times"] = result.frames;
  summary["vtk_frames"] = frames.size();
  write("summary.json", summary.dump(2) + "\n");
  return result;
}

}  // namespace bpm
