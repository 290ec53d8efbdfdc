#include "io/scenario_run.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <optional>

#include "io/atomic_file.hpp"
#include "io/probe_recorder.hpp"
#include "io/state_csv.hpp"
#include "io/summary_json.hpp"
#include "io/vtk_writer.hpp"

namespace bpm {
namespace {
/// One row per broken bond, in the order they broke: the pair (user ids), time, mode, position.
std::string bond_breaks_csv(const Model& model, double dt) {
  const BondStore& b = model.bonds;
  const ParticleStore& p = model.particles;
  std::string s = "bond,particle_alpha,particle_beta,time_s,mode,x,y,z\n";
  for (const BondStore::Break& e : b.breaks) {
    s += fmt::format("{},{},{},{:.10g},{},{:.10g},{:.10g},{:.10g}\n", e.bond, p.id[b.alpha[e.bond]], p.id[b.beta[e.bond]],
                     static_cast<double>(e.update) * dt, e.mode == BreakMode::tension ? "tension" : "shear",
                     e.position.x, e.position.y, e.position.z);
  }
  return s;
}

/// One row of walls.csv: time, then per wall its displacement since t = 0 and the force the
/// particles exert on it (the header first when `header`).
std::string walls_row(const std::vector<Wall>& walls, double t, bool header) {
  std::string s;
  if (header) {
    s = "time";
    for (const Wall& w : walls) {
      for (const char* c : {"ux", "uy", "uz", "fx", "fy", "fz"}) s += fmt::format(",{}_{}", w.name, c);
    }
    s += "\n";
  }
  s += fmt::format("{:.10g}", t);
  for (const Wall& w : walls) {
    s += fmt::format(",{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", w.displacement.x, w.displacement.y,
                     w.displacement.z, w.force.x, w.force.y, w.force.z);
  }
  return s + "\n";
}

std::string force_displacement_csv(const CompressionResult& r) {
  std::string s = "time_s,displacement_m,strain,force_N,stress_Pa,force_top_N,force_bottom_N,kinetic_J,elastic_J,bonds_broken\n";
  for (const CompressionPoint& p : r.curve) {
    s += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{}\n", p.time,
                     p.displacement, p.strain, p.force, p.force / r.sample.area, p.force_top, p.force_bottom, p.kinetic,
                     p.elastic, p.bonds_broken);
  }
  return s;
}

nlohmann::json compression_json(const CompressionResult& r) {
  return {{"sample_length_m", r.sample.length},
          {"sample_area_m2", r.sample.area},
          {"stiffness_N_per_m", r.stiffness},
          {"youngs_modulus_Pa", r.youngs_modulus},
          {"fit_r2", r.fit_r2},
          {"fit_points", r.fit_points},
          {"max_kinetic_to_elastic_energy", r.max_kinetic_ratio},
          {"max_platen_force_imbalance", r.max_force_imbalance},
          {"peak_stress_Pa", r.peak_stress},
          {"peak_strain", r.peak_strain},
          {"time_step_s", r.time_step},
          {"stop", r.stop}};
}

}  // namespace

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
