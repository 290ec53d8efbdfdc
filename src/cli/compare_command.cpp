// `bpmkit compare SCENARIO`: the DEM, linear DSM, nonlinear DSM and STE on the same sample under
// the same compression; a table of stiffness, error against the DEM, wall time and speed-up
// (Jarolin Fig. 4). Writes compare.csv and compare.json. The scaling with sample size (Jarolin
// Fig. 5) needs independently generated samples (a cut of one sample has cut faces against the
// platens): scripts/validation_study.py --fig5.
#include <fmt/core.h>

#include <fstream>
#include <memory>

#include "dsm/dsm_linear.hpp"
#include "cli/commands.hpp"
#include "cli/dem_progress.hpp"
#include "cli/stiffness_options.hpp"
#include "core/error.hpp"
#include "solvers/mpi_world.hpp"
#include "io/log.hpp"
#include "io/output_folder.hpp"

namespace bpm::cli {
namespace {

struct Options : StiffnessCliOptions {
  std::vector<std::string> methods{"dsm", "dsm-nonlinear", "ste"};
  std::string reference = "dem";
  std::string reference_from;  ///< stiffness.json of an earlier `bpmkit stiffness` run of the reference
};

/// The reference estimate from an earlier `bpmkit stiffness` output (a DEM of the full sample takes
/// minutes to hours; its K and wall time are all the table needs).
StiffnessEstimate read_reference(const std::string& path, const std::string& scenario) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot be read", "give the stiffness.json written by `bpmkit stiffness --method dem`");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, std::string("is not valid JSON: ") + e.what(), "give the stiffness.json written by `bpmkit stiffness`");
  }
  if (j.value("scenario", std::string()) != scenario) {
    throw InputError(path, "was written for scenario '" + j.value("scenario", std::string()) + "', not '" + scenario + "'",
                     "run `bpmkit stiffness --method dem` on this scenario");
  }
  StiffnessEstimate e = stiffness_estimate_from_json(j, path);
  e.details["read_from"] = path;
  return e;
}

/// Runs the reference and the methods, prints and writes the table; returns the summary.
nlohmann::json compare(const Options& o, const Scenario& scenario, const StiffnessSettings& settings,
                       StiffnessMethod reference, const std::vector<StiffnessMethod>& methods,
                       const OutputFolder& folder) {
  std::string csv =
      "particles,bonds,method,stiffness_N_per_m,youngs_modulus_Pa,error_vs_reference,wall_s,speed_up,"
      "max_field_difference\n";
  nlohmann::json rows = nlohmann::json::array();
  {
    const Model& model = scenario.model;
    fmt::print("\n{} particles, {} bonds\n", model.particles.size(), model.bonds.size());
    fmt::print("{:<14} {:>14} {:>14} {:>10} {:>10} {:>10} {:>12}\n", "method", "K [N/m]", "E [Pa]", "error", "wall [s]",
               "speed-up", "field diff");
    const DemProgress progress(progress_plan(settings.compression));
    const StiffnessEstimate ref = !o.reference_from.empty() ? read_reference(o.reference_from, o.scenario)
                                                            : estimate_sample_stiffness(model, reference, settings);
    const PlatenLoading load = make_platen_loading(model, settings.compression);
    auto row = [&](const StiffnessEstimate& e) {
      const double error = e.stiffness / ref.stiffness - 1.0;
      const double speed_up = e.seconds > 0.0 ? ref.seconds / e.seconds : 0.0;
      // Particle by particle, where both give a displacement field (DSM and DEM), relative to the
      // platen displacement.
      const bool fields = !e.displacement.empty() && !ref.displacement.empty() && &e != &ref;
      const double field = fields ? max_relative_difference(model, load, e.displacement, ref.displacement) : 0.0;
      log::result("{:<14} {:>14.6g} {:>14.6g} {:>9.2f}% {:>10.3f} {:>10.1f} {:>12}\n", to_string(e.method), e.stiffness,
                  e.youngs_modulus, 100.0 * error, e.seconds, speed_up, fields ? fmt::format("{:.3g}", field) : "");
      csv += fmt::format("{},{},{},{:.9g},{:.9g},{:.6g},{:.6g},{:.6g},{}\n", model.particles.size(), model.bonds.size(),
                         to_string(e.method), e.stiffness, e.youngs_modulus, error, e.seconds, speed_up,
                         fields ? fmt::format("{:.6g}", field) : "");
      nlohmann::json json = to_json(e);
      json["particles"] = model.particles.size();
      json["bonds"] = model.bonds.size();
      json["error_vs_reference"] = error;
      json["speed_up"] = speed_up;
      json["max_field_difference"] = fields ? nlohmann::json(field) : nlohmann::json(nullptr);
      rows.push_back(std::move(json));
    };
    row(ref);
    for (const StiffnessMethod m : methods) {
      if (m != ref.method) row(estimate_sample_stiffness(model, m, settings));
    }
  }
  folder.write("compare.csv", csv);
  folder.write("compare.json",
               nlohmann::json{{"scenario", o.scenario}, {"reference", o.reference}, {"rows", rows}}.dump(2) + "\n");
  log::info("\nwrote {} and compare.json\n", folder.path("compare.csv"));
  return {{"scenario", o.scenario}, {"reference", o.reference}};
}


void run(const Options& o) {
  Scenario scenario = load_compression_scenario(o.scenario);
  const StiffnessSettings settings = make_stiffness_settings(scenario, o);
  const StiffnessMethod reference = parse_stiffness_method(o.reference, "--reference");
  std::vector<StiffnessMethod> methods;
  for (const auto& name : o.methods) methods.push_back(parse_stiffness_method(name, "--methods"));
  // Under mpirun the DEM reference is read from an earlier run (--reference-from); the methods are
  // divided between the ranks.
  require_methods_across_ranks(methods, "--methods");
  if (mpi::world().distributed() && o.reference_from.empty()) {
    throw InputError("--reference " + o.reference, "does not run across MPI ranks",
                     "give --reference-from the stiffness.json of a `bpmkit stiffness --method dem` run without mpirun");
  }
  OutputFolder folder(o.out_dir, "compare", {"compare.csv", "compare.json"}, o.overwrite);
  log_settings(o);
  folder.run([&] { return compare(o, scenario, settings, reference, methods, folder); });
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("compare", "DEM, DSM, nonlinear DSM and STE on the same sample: stiffness, error, speed-up");
  auto o = std::make_shared<Options>();
  add_stiffness_options(cmd, *o, "out/compare");
  cmd->add_option("--methods", o->methods, "methods to compare with the reference")->capture_default_str();
  cmd->add_option("--reference", o->reference, "the reference: dem (platens) or dem-kinematic")->capture_default_str();
  cmd->add_option("--reference-from", o->reference_from,
                  "stiffness.json of an earlier `bpmkit stiffness` run of the reference on this scenario");
  cmd->callback([o] { run(*o); });
}

}  // namespace bpm::cli
