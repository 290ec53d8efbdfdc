// `bpmkit calibrate --target-E VALUE SCENARIO`: the bond Young's modulus that gives the sample the
// target stiffness (Jarolin section 5): by default the linear DSM with its platen walls, then the
// nonlinear DSM from its answer, then the DEM (its error at that answer, one corrected run;
// --no-dem stops at the fast answer); other stages on request (STE). Prints each stage's moduli,
// stiffness and error (against the target, by the stage's own method), the method's measured error
// against the DEM, the DEM's own error at the fast answer, and writes calibration.json.
#include <fmt/core.h>

#include <algorithm>
#include <memory>

#include "calibrate/bond_youngs_modulus.hpp"
#include "calibrate/calibration.hpp"
#include "calibrate/validation.hpp"
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
  double target_E = 0.0;
  double target_K = 0.0;
  std::vector<std::string> stages{"dsm", "dsm-nonlinear"};
  std::vector<std::string> materials;  ///< calibrate only these (others fixed); empty: all, one scale
  bool confirm_dem = false;
  bool no_dem = false;
  std::string dem = "dem";
  double calibration_tolerance = 1e-3;
};

/// Runs the stages, prints and writes them; returns the summary.
nlohmann::json calibrate(const Options& o, const Scenario& scenario, const CalibrationSettings& s,
                         const SampleGeometry& sample, const OutputFolder& folder) {
  const auto& names = scenario.bond_material_names;
  log::info("{}: {} particles, {} bonds; sample l = {:.6g} m, A = {:.6g} m^2\n", o.scenario,
            scenario.model.particles.size(), scenario.model.bonds.size(), sample.length, sample.area);
  fmt::print("target: K = {:.6g} N/m (E = {:.6g} Pa)\n", s.target_stiffness, s.target_stiffness * sample.length / sample.area);
  auto moduli = [&](const std::vector<double>& e) {
    std::string text;
    for (std::size_t m = 0; m < e.size(); ++m) text += fmt::format("{}{} = {:.6g} Pa", m ? ", " : "", names[m], e[m]);
    return text;
  };
  log::info("start:  {}\n", moduli(bond_youngs_moduli(scenario.bond_materials)));

  const CalibrationResult r = [&] {
    const DemProgress progress(progress_plan(s.stiffness.compression));
    return calibrate_bond_youngs_modulus(scenario.model, scenario.bond_materials, s);
  }();
  nlohmann::json stages = nlohmann::json::array();
  std::string previous;
  for (const CalibrationStage& st : r.stages) {
    const std::string method(to_string(st.method));
    const bool dem = st.method == StiffnessMethod::dem || st.method == StiffnessMethod::dem_kinematic;
    if (dem && !previous.empty()) {
      log::info("{:<14} one secant step from there with d ln K / d ln E_b = {:.3f} (by {})\n", "", r.sensitivity,
                 previous);
    }
    fmt::print("{:<14} {}   K = {:.6g} N/m   error {:+.3f} % against the target, K by {} itself   {} evaluations, {:.2f} s\n",
               method, moduli(st.youngs_moduli), st.stiffness, 100.0 * st.error, method, st.evaluations, st.seconds);
    nlohmann::json entry = {{"method", method},
                            {"stiffness_N_per_m", st.stiffness},
                            {"relative_error", st.error},
                            {"error_measured_by", method},
                            {"evaluations", st.evaluations},
                            {"wall_s", st.seconds}};
    if (!st.reached) {
      fmt::print("{:<14} out of {}'s reach; the next stage starts from this one's start\n", "", method);
      entry["reached"] = false;
    }
    if (const auto v = validated_error(st.method)) {
      log::info("{:<14} {}'s K against the DEM with platens (docs/validation.md): mean |error| {:.1f} %, max {:.1f} % "
                 "on {} bond-dominated samples; {:.1f} %, max {:.1f} % on {} contact-dominated ones\n",
                 "", method, 100.0 * v->bond_dominated.mean_abs, 100.0 * v->bond_dominated.max_abs,
                 v->bond_dominated.samples, 100.0 * v->contact_dominated.mean_abs, 100.0 * v->contact_dominated.max_abs,
                 v->contact_dominated.samples);
      auto json = [](const MeasuredError& m) {
        return nlohmann::json{{"mean_abs", m.mean_abs}, {"max_abs", m.max_abs}, {"samples", m.samples}};
      };
      entry["validated_error_vs_dem"] = {{"bond_dominated", json(v->bond_dominated)},
                                         {"contact_dominated", json(v->contact_dominated)}};
    }
    if (dem && !previous.empty()) {
      fmt::print("{:<14} the DEM at the {} answer: error {:+.3f} % against the target\n", "", previous,
                 100.0 * st.start_error);
      entry["dem_error_at_previous_answer"] = st.start_error;
    }
    nlohmann::json e = nlohmann::json::object();
    for (std::size_t m = 0; m < st.youngs_moduli.size(); ++m) e[names[m]] = st.youngs_moduli[m];
    entry["bond_youngs_modulus_Pa"] = e;
    stages.push_back(entry);
    previous = method;
  }
  if (!r.stages.empty()) {
    fmt::print("answer ({}): {}\n", to_string(r.stages.back().method), moduli(r.youngs_moduli));
    const StiffnessMethod last = r.stages.back().method;
    if (last != StiffnessMethod::dem && last != StiffnessMethod::dem_kinematic && r.sensitivity > 0.0) {
      // E_b's error is about K's error against the DEM divided by the sensitivity.
      const auto v = validated_error(last);
      fmt::print("no DEM stage: d ln K / d ln E_b = {:.3f}, so E_b's error is about {}'s K error against the DEM over "
                 "{:.3f}{}\n",
                 r.sensitivity, to_string(last), r.sensitivity,
                 v ? fmt::format(": up to {:.1f} % on bond-dominated and {:.1f} % on contact-dominated samples",
                                 100.0 * v->bond_dominated.max_abs / r.sensitivity,
                                 100.0 * v->contact_dominated.max_abs / r.sensitivity)
                   : std::string());
    }
  }
  nlohmann::json json = {{"scenario", o.scenario},
                         {"target_stiffness_N_per_m", s.target_stiffness},
                         {"target_youngs_modulus_Pa", s.target_stiffness * sample.length / sample.area},
                         {"sample_length_m", sample.length},
                         {"sample_area_m2", sample.area},
                         {"sensitivity_dlnK_dlnEb", r.sensitivity},
                         {"stages", stages}};
  log::info("wrote {}\n", folder.write("calibration.json", json.dump(2) + "\n"));
  json.erase("stages");  // summary.json: the answer; calibration.json has every stage
  json["bond_youngs_modulus_Pa"] = stages.empty() ? nlohmann::json(nullptr) : stages.back()["bond_youngs_modulus_Pa"];
  return json;
}


void run(const Options& o) {
  Scenario scenario = load_compression_scenario(o.scenario);
  CalibrationSettings s;
  s.stiffness = make_stiffness_settings(scenario, o);
  s.bond_damping = scenario.model.damping.bond;
  s.tolerance = o.calibration_tolerance;
  s.stages.clear();
  for (const auto& name : o.stages) s.stages.push_back(parse_stiffness_method(name, "--stages"));
  if (o.confirm_dem && o.no_dem) throw InputError("calibrate", "--confirm-dem and --no-dem contradict each other", "give one of them");
  s.finish_with_dem = !o.no_dem;  // --confirm-dem: the default, kept for scripts that give it
  s.dem_method = parse_stiffness_method(o.dem, "--dem");
  require_methods_across_ranks(s.stages, "--stages");
  if (mpi::world().distributed() && s.finish_with_dem) {
    throw InputError("calibrate", "the DEM stage does not run across MPI ranks",
                     "give --no-dem, or run without mpirun for the DEM stages");
  }

  const SampleGeometry sample = measure_sample(scenario.model.particles, s.stiffness.compression.axis);
  if ((o.target_E > 0.0) == (o.target_K > 0.0)) {
    throw InputError("calibrate", "give exactly one target", "--target-E PASCAL (sample Young's modulus) or --target-K N_PER_M");
  }
  s.target_stiffness = o.target_K > 0.0 ? o.target_K : o.target_E * sample.area / sample.length;

  const auto& names = scenario.bond_material_names;
  if (!o.materials.empty()) {
    s.calibrated_materials.assign(names.size(), false);
    for (const auto& m : o.materials) {
      const auto it = std::find(names.begin(), names.end(), m);
      if (it == names.end()) throw InputError("--materials", "no bond material '" + m + "'", "the scenario's bond materials are listed under bond_materials");
      s.calibrated_materials[static_cast<std::size_t>(it - names.begin())] = true;
    }
  }
  OutputFolder folder(o.out_dir, "calibrate", {"calibration.json"}, o.overwrite);
  log_settings(o);
  folder.run([&] { return calibrate(o, scenario, s, sample, folder); });
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("calibrate", "find the bond Young's modulus for a target sample stiffness");
  auto o = std::make_shared<Options>();
  add_stiffness_options(cmd, *o, "out/calibrate");
  cmd->add_option("--target-E", o->target_E, "target sample Young's modulus, Pa (K = E A / l)");
  cmd->add_option("--target-K", o->target_K, "target sample stiffness, N/m");
  cmd->add_option("--stages", o->stages,
                  "methods in order, each starting from the last one's answer (docs/validation.md has each one's "
                  "error against the DEM): dsm, dsm-nonlinear, ste (a first guess), dsm-kinematic")
      ->capture_default_str();
  cmd->add_option("--materials", o->materials, "calibrate only these bond materials (default: all, ratios fixed)");
  cmd->add_flag("--confirm-dem", o->confirm_dem,
                "finish with the explicit DEM (the default): its error at the fast answer, then one corrected run");
  cmd->add_flag("--no-dem", o->no_dem,
                "stop at the fast answer (seconds instead of two DEM runs; its expected error is printed)");
  cmd->add_option("--dem", o->dem, "the DEM of the DEM stage: dem (platens) or dem-kinematic")->capture_default_str();
  cmd->add_option("--calibration-tolerance", o->calibration_tolerance, "stop a stage at |K/K_target - 1| below this")
      ->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace bpm::cli
