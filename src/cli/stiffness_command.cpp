// `bpmkit stiffness --method dsm|dsm-nonlinear|ste|dem|dsm-kinematic|dem-kinematic SCENARIO`: the sample stiffness
// K and E = K l / A under the scenario's uniaxial compression, by one method; writes
// stiffness.json and, for the DSM and DEM, the displacement field as VTK.
#include <fmt/core.h>

#include <memory>

#include "cli/commands.hpp"
#include "cli/dem_progress.hpp"
#include "cli/stiffness_options.hpp"
#include "core/error.hpp"
#include "solvers/mpi_world.hpp"
#include "io/log.hpp"
#include "io/output_folder.hpp"
#include "io/vtk_writer.hpp"
#include "ste/ste_vtk.hpp"

namespace bpm::cli {
namespace {

struct Options : StiffnessCliOptions {
  std::string method = "dsm";
};

/// Estimates K, writes the files (the VTK ones only if the scenario's `output.vtk` is on); returns
/// the summary.
nlohmann::json estimate(const Options& o, const Model& model, StiffnessMethod method, const StiffnessSettings& settings,
                        bool write_vtk, const OutputFolder& folder) {
  const StiffnessEstimate e = [&] {
    const DemProgress progress(progress_plan(settings.compression));
    return estimate_sample_stiffness(model, method, settings);
  }();
  fmt::print("sample l = {:.6g} m, A = {:.6g} m^2\n", e.sample.length, e.sample.area);
  print_estimate(e);

  nlohmann::json json = to_json(e);
  json["scenario"] = o.scenario;
  folder.write("stiffness.json", json.dump(2) + "\n");
  if (write_vtk && !e.displacement.empty()) {
    // The displaced sample: VTK point field `displacement` (and positions) of the static solution.
    Model displaced = model;
    for (std::size_t i = 0; i < e.displacement.size(); ++i) {
      displaced.particles.position[i] = displaced.particles.reference_position[i] + e.displacement[i];
    }
    folder.write("displacement.vtp", polydata_vtp(displaced));
  }
  // The STE's map of the 8e5-particle box is 431 MB of text, 2-3 times the STE's own time.
  if (write_vtk && e.ste && !OutputFolder::silent()) ste::write_ste_vtp(folder.path("stiffness_map.vtp"), model.particles, *e.ste);
  log::info("wrote {}\n", folder.path("stiffness.json"));
  json.erase("details");  // summary.json: the answer; stiffness.json has the method's details
  // The ranks and each one's peak memory (a collective: every rank gets here).
  json["mpi_ranks"] = mpi::world().size;
  json["peak_memory_per_rank_bytes"] = mpi::peak_memory_per_rank();
  return json;
}

void run(const Options& o) {
  const StiffnessMethod method = parse_stiffness_method(o.method, "--method");
  require_methods_across_ranks({method}, "--method");
  const bool in_time = method == StiffnessMethod::dem || method == StiffnessMethod::dem_kinematic;
  Scenario scenario = load_compression_scenario(o.scenario, in_time);
  StiffnessSettings settings = make_stiffness_settings(scenario, o);
  settings.ste.local_map = true;  // for stiffness_map.vtp
  OutputFolder folder(o.out_dir, "stiffness", {"stiffness.json", "displacement.vtp", "stiffness_map.vtp"}, o.overwrite);
  const Model& model = scenario.model;
  log::info("{}: {} particles, {} bonds; compression along [{}, {}, {}] to strain {}\n", o.scenario,
            model.particles.size(), model.bonds.size(), settings.compression.axis.x, settings.compression.axis.y,
            settings.compression.axis.z, settings.compression.target_strain);
  log_settings(o);
  folder.run([&] { return estimate(o, model, method, settings, scenario.output.vtk, folder); });
}

}  // namespace

void add_stiffness_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("stiffness", "sample stiffness K and E under the scenario's uniaxial compression");
  auto options = std::make_shared<Options>();
  add_stiffness_options(cmd, *options, "out/stiffness");
  cmd->add_option("--method", options->method,
                  "dsm (linear, with the platen walls), dsm-nonlinear, ste, dem (the reference), or the kinematic "
                  "platens' dsm-kinematic and dem-kinematic")
      ->capture_default_str();
  cmd->callback([options] { run(*options); });
}

}  // namespace bpm::cli
