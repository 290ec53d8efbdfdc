// `bpmkit calibrate --target-E PA [--target-nu NU] SCENARIO`: the bond parameters that give the
// body the target Young's modulus (and Poisson's ratio), both from strain gauges on its middle
// third; or `--target-K` / `--target-platen-E` for Jarolin's platen stiffness (section 5). By
// default the linear DSM with its platen walls, then the nonlinear DSM from its answer, then the
// DEM (its error at that answer, one corrected run; --no-dem stops at the fast answer); other
// stages on request (STE). Prints each stage's parameters, E, nu, K and errors (by the stage's own
// method), the method's measured error against the DEM, the DEM's own error at the fast answer,
// and writes calibration.json and calibrated.yaml (the scenario with the answer, for `bpmkit run`).
#include <fmt/core.h>

#include <algorithm>
#include <memory>

#include "calibrate/bond_parameters.hpp"
#include "calibrate/calibration.hpp"
#include "calibrate/validation.hpp"
#include "cli/calibrate_strength.hpp"
#include "cli/commands.hpp"
#include "cli/dem_progress.hpp"
#include "cli/stiffness_options.hpp"
#include "core/error.hpp"
#include "io/log.hpp"
#include "io/output_folder.hpp"
#include "scenario/calibrated_scenario.hpp"
#include "solvers/mpi_world.hpp"

namespace bpm::cli {
namespace {

struct Options : StiffnessCliOptions {
  double target_E = 0.0;
  double target_platen_E = 0.0;
  double target_K = 0.0;
  std::optional<double> target_nu;
  std::vector<std::string> stages{"dsm", "dsm-nonlinear"};
  std::vector<std::string>
      materials;  ///< calibrate only these (others fixed); empty: all, one scale
  bool confirm_dem = false;
  bool no_dem = false;
  std::string dem = "dem";
  double calibration_tolerance = 1e-3;
  double nu_tolerance = 1e-3;
  StrengthOptions strength;
};

/// The answer's bond materials: the scenario's with the last stage's E_b and k_s / k_n.
std::vector<BondMaterial> answer_materials(const Scenario& scenario, const CalibrationResult& r) {
  std::vector<BondMaterial> materials = scenario.bond_materials;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    materials[m].youngs_modulus = r.youngs_moduli[m];
    if (!r.shear_to_normal_ratios.empty() && r.shear_to_normal_ratios[m] > 0.0) {
      set_shear_to_normal_ratio(materials[m], r.shear_to_normal_ratios[m]);
    }
  }
  return materials;
}

/// Runs the stages, prints and writes them; returns the summary.
nlohmann::json calibrate(const Options& o, const Scenario& scenario, const CalibrationSettings& s,
                         std::vector<BondMaterial>& answer_out, const SampleGeometry& sample,
                         const OutputFolder& folder) {
  const auto& names = scenario.bond_material_names;
  const bool by_stiffness = s.quantity == CalibrationQuantity::stiffness;
  const bool fit_nu = s.target_poissons_ratio.has_value();
  log::info("{}: {} particles, {} bonds; sample l = {:.6g} m, A = {:.6g} m^2\n", o.scenario,
            scenario.model.particles.size(), scenario.model.bonds.size(), sample.length,
            sample.area);
  const std::string nu_text =
      fit_nu ? fmt::format(", the body's nu = {:.4g}", *s.target_poissons_ratio) : "";
  if (by_stiffness) {
    fmt::print("target: K = {:.6g} N/m (K l / A = {:.6g} Pa, the platens' travel){}\n", s.target,
               s.target * sample.length / sample.area, nu_text);
  } else {
    fmt::print("target: the body's E = {:.6g} Pa (strain gauges on its middle third){}\n", s.target,
               nu_text);
  }
  auto parameters = [&](const std::vector<double>& e, const std::vector<double>& ratio) {
    std::string text;
    for (std::size_t m = 0; m < e.size(); ++m) {
      text += fmt::format("{}{}: E_b = {:.6g} Pa", m ? ", " : "", names[m], e[m]);
      if (!ratio.empty() && ratio[m] > 0.0) text += fmt::format(" k_s/k_n = {:.4g}", ratio[m]);
    }
    return text;
  };
  std::vector<double> start_ratio;
  for (std::size_t m = 0; fit_nu && m < names.size(); ++m) {
    const bool chosen = s.calibrated_materials.empty() || s.calibrated_materials[m];
    start_ratio.push_back(chosen ? shear_to_normal_ratio(scenario.bond_materials[m]) : 0.0);
  }
  log::info("start:  {}\n", parameters(bond_youngs_moduli(scenario.bond_materials), start_ratio));

  const CalibrationResult r = [&] {
    const DemProgress progress(progress_plan(s.stiffness.compression));
    return calibrate_bond_parameters(scenario.model, scenario.bond_materials, s);
  }();
  if (r.poissons_ratio_range) {
    log::info(
        "nu reachable by k_s / k_n alone: {:.4f} (k_s/k_n = {:g}) to {:.4f} (k_s/k_n = {:g}), by "
        "{}\n",
        r.poissons_ratio_range->low, kMaxShearToNormalRatio, r.poissons_ratio_range->high,
        kMinShearToNormalRatio, to_string(r.poissons_ratio_range->method));
  }
  nlohmann::json stages = nlohmann::json::array();
  std::string previous;
  const std::string quantity(to_string(s.quantity));
  for (const CalibrationStage& st : r.stages) {
    const std::string method(to_string(st.method));
    const bool dem =
        st.method == StiffnessMethod::dem || st.method == StiffnessMethod::dem_kinematic;
    if (dem && !previous.empty()) {
      log::info("{:<14} one {} step from there with d ln {} / d ln E_b = {:.3f} (by {})\n", "",
                fit_nu ? "Newton" : "secant", quantity, r.sensitivity, previous);
    }
    const std::string nu = fit_nu ? fmt::format(", nu {:+.4f}", st.poissons_ratio_error) : "";
    const bool body = st.measured.youngs_modulus > 0.0;  // a kinematic method has no strain gauges
    fmt::print(
        "{:<14} {}   {}K = {:.6g} N/m   error {:+.3f} % ({}){} against the target, by {} itself   "
        "{} evaluations, {:.2f} s\n",
        method, parameters(st.youngs_moduli, st.shear_to_normal_ratios),
        body ? fmt::format("E = {:.6g} Pa  nu = {:.4f}  ", st.measured.youngs_modulus,
                           st.measured.poissons_ratio)
             : std::string(),
        st.measured.stiffness, 100.0 * st.error, quantity, nu, method, st.evaluations, st.seconds);
    nlohmann::json entry = {
        {"method", method},
        {"stiffness_N_per_m", st.measured.stiffness},
        {"youngs_modulus_Pa", body ? nlohmann::json(st.measured.youngs_modulus) : nullptr},
        {"poissons_ratio", body ? nlohmann::json(st.measured.poissons_ratio) : nullptr},
        {"relative_error", st.error},
        {"error_measured_by", method},
        {"evaluations", st.evaluations},
        {"wall_s", st.seconds}};
    if (fit_nu) entry["poissons_ratio_error"] = st.poissons_ratio_error;
    if (!st.reached) {
      fmt::print("{:<14} out of {}'s reach; the next stage starts from this one's start\n", "",
                 method);
      entry["reached"] = false;
    }
    if (const auto v = validated_error(st.method)) {
      log::info(
          "{:<14} {}'s K against the DEM with platens (docs/validation.md): mean |error| {:.1f} %, "
          "max {:.1f} % "
          "on {} bond-dominated samples; {:.1f} %, max {:.1f} % on {} contact-dominated ones\n",
          "", method, 100.0 * v->bond_dominated.mean_abs, 100.0 * v->bond_dominated.max_abs,
          v->bond_dominated.samples, 100.0 * v->contact_dominated.mean_abs,
          100.0 * v->contact_dominated.max_abs, v->contact_dominated.samples);
      auto json = [](const MeasuredError& m) {
        return nlohmann::json{
            {"mean_abs", m.mean_abs}, {"max_abs", m.max_abs}, {"samples", m.samples}};
      };
      entry["validated_error_vs_dem"] = {{"bond_dominated", json(v->bond_dominated)},
                                         {"contact_dominated", json(v->contact_dominated)}};
    }
    if (dem && !previous.empty()) {
      fmt::print(
          "{:<14} the DEM at the {} answer: error {:+.3f} % ({}){} against the target\n", "",
          previous, 100.0 * st.start_error, quantity,
          fit_nu ? fmt::format(", nu {:+.4f}", st.start_poissons_ratio_error) : std::string());
      entry["dem_error_at_previous_answer"] = st.start_error;
      if (fit_nu)
        entry["dem_poissons_ratio_error_at_previous_answer"] = st.start_poissons_ratio_error;
    }
    nlohmann::json e = nlohmann::json::object(), ratio = nlohmann::json::object();
    for (std::size_t m = 0; m < st.youngs_moduli.size(); ++m) {
      e[names[m]] = st.youngs_moduli[m];
      if (!st.shear_to_normal_ratios.empty() && st.shear_to_normal_ratios[m] > 0.0) {
        ratio[names[m]] = st.shear_to_normal_ratios[m];
      }
    }
    entry["bond_youngs_modulus_Pa"] = e;
    if (fit_nu) entry["bond_shear_to_normal_ratio"] = ratio;
    stages.push_back(entry);
    previous = method;
  }
  const std::vector<BondMaterial> answer = answer_materials(scenario, r);
  answer_out = answer;
  if (!r.stages.empty()) {
    fmt::print("answer ({}): {}\n", to_string(r.stages.back().method),
               parameters(r.youngs_moduli, r.shear_to_normal_ratios));
    if (fit_nu) {
      for (std::size_t m = 0; m < answer.size(); ++m) {
        if (r.shear_to_normal_ratios[m] > 0.0) {
          fmt::print("{:<14} {}: {} = {:.6g}\n", "", names[m], shear_ratio_parameter(answer[m]),
                     shear_ratio_parameter_value(answer[m]));
        }
      }
    }
    const StiffnessMethod last = r.stages.back().method;
    if (last != StiffnessMethod::dem && last != StiffnessMethod::dem_kinematic &&
        r.sensitivity > 0.0) {
      // E_b's error is about K's error against the DEM divided by the sensitivity.
      const auto v = validated_error(last);
      fmt::print(
          "no DEM stage: d ln {} / d ln E_b = {:.3f}, so E_b's error is about {}'s {} error "
          "against the DEM over "
          "{:.3f}{}\n",
          quantity, r.sensitivity, to_string(last), quantity, r.sensitivity,
          v && by_stiffness
              ? fmt::format(
                    ": up to {:.1f} % on bond-dominated and {:.1f} % on contact-dominated samples",
                    100.0 * v->bond_dominated.max_abs / r.sensitivity,
                    100.0 * v->contact_dominated.max_abs / r.sensitivity)
              : std::string());
    }
  }
  nlohmann::json json = {
      {"scenario", o.scenario},
      {"target_quantity", by_stiffness ? "stiffness" : "youngs_modulus"},
      {"sample_length_m", sample.length},
      {"sample_area_m2", sample.area},
      {by_stiffness ? "sensitivity_dlnK_dlnEb" : "sensitivity_dlnE_dlnEb", r.sensitivity},
      {"stages", stages}};
  if (by_stiffness) {
    json["target_stiffness_N_per_m"] = s.target;
    json["target_platen_youngs_modulus_Pa"] = s.target * sample.length / sample.area;
  } else {
    json["target_youngs_modulus_Pa"] = s.target;
  }
  if (fit_nu) {
    json["target_poissons_ratio"] = *s.target_poissons_ratio;
    if (r.jacobian) json["jacobian_lnE_nu_by_lnEb_lnratio"] = *r.jacobian;
    if (r.poissons_ratio_range) {
      json["poissons_ratio_range"] = {
          {"method", std::string(to_string(r.poissons_ratio_range->method))},
          {"min", r.poissons_ratio_range->low},
          {"max", r.poissons_ratio_range->high},
          {"shear_to_normal_ratio_at_min", kMaxShearToNormalRatio},
          {"shear_to_normal_ratio_at_max", kMinShearToNormalRatio}};
    }
  }
  log::info("wrote {}\n", folder.write("calibration.json", json.dump(2) + "\n"));
  if (!r.stages.empty()) {
    const std::string header = fmt::format(
        "bpmkit calibrate: {} with the bond parameters of its last stage ({}); calibration.json "
        "has every stage",
        o.scenario, to_string(r.stages.back().method));
    log::info(
        "wrote {} (bpmkit run runs it as it is)\n",
        folder.write("calibrated.yaml", calibrated_scenario_yaml(o.scenario, answer, fit_nu, false,
                                                                 folder.dir(), {header})));
  }
  json["bond_youngs_modulus_Pa"] =
      stages.empty() ? nlohmann::json(nullptr) : stages.back()["bond_youngs_modulus_Pa"];
  if (fit_nu && !stages.empty())
    json["bond_shear_to_normal_ratio"] = stages.back()["bond_shear_to_normal_ratio"];
  return json;
}

void run(const Options& o) {
  Scenario scenario = load_compression_scenario(o.scenario);
  CalibrationSettings s;
  s.stiffness = make_stiffness_settings(scenario, o);
  s.bond_damping = scenario.model.damping.bond;
  if (!scenario.time_step_given) s.time_step_safety = scenario.safety_factor;
  s.tolerance = o.calibration_tolerance;
  s.poissons_ratio_tolerance = o.nu_tolerance;
  s.stages.clear();
  for (const auto& name : o.stages) s.stages.push_back(parse_stiffness_method(name, "--stages"));
  if (o.confirm_dem && o.no_dem)
    throw InputError("calibrate", "--confirm-dem and --no-dem contradict each other",
                     "give one of them");
  s.finish_with_dem = !o.no_dem;  // --confirm-dem: the default, kept for scripts that give it
  s.dem_method = parse_stiffness_method(o.dem, "--dem");
  require_methods_across_ranks(s.stages, "--stages");
  if (mpi::world().distributed() && s.finish_with_dem) {
    throw InputError("calibrate", "the DEM stage does not run across MPI ranks",
                     "give --no-dem, or run without mpirun for the DEM stages");
  }

  const SampleGeometry sample =
      measure_sample(scenario.model.particles, s.stiffness.compression.axis);
  const int elastic_targets = (o.target_E > 0.0) + (o.target_platen_E > 0.0) + (o.target_K > 0.0);
  const bool strength = o.strength.target_ucs > 0.0 || o.strength.target_bts > 0.0;
  if (o.target_nu && o.target_E <= 0.0) {
    throw InputError("--target-nu", "needs --target-E: nu and E are calibrated together",
                     "give --target-E too");
  }
  if (elastic_targets > 1 || (elastic_targets == 0 && !strength)) {
    throw InputError("calibrate", "give exactly one target for the stiffness",
                     "--target-E PASCAL (the body's Young's modulus, as strain gauges measure it), "
                     "--target-K N_PER_M "
                     "(the platen stiffness) or --target-platen-E PASCAL (K l / A)");
  }
  if (o.target_E > 0.0 || elastic_targets == 0) {
    s.quantity = CalibrationQuantity::youngs_modulus;
    s.target = o.target_E;
  } else {
    s.quantity = CalibrationQuantity::stiffness;
    s.target = o.target_K > 0.0 ? o.target_K : o.target_platen_E * sample.area / sample.length;
  }
  s.target_poissons_ratio = o.target_nu;

  const auto& names = scenario.bond_material_names;
  if (!o.materials.empty()) {
    s.calibrated_materials.assign(names.size(), false);
    for (const auto& m : o.materials) {
      const auto it = std::find(names.begin(), names.end(), m);
      if (it == names.end())
        throw InputError("--materials", "no bond material '" + m + "'",
                         "the scenario's bond materials are listed under bond_materials");
      s.calibrated_materials[static_cast<std::size_t>(it - names.begin())] = true;
    }
  }
  if (o.target_nu) {  // a model without a free k_s / k_n is refused before the folder is claimed
    for (std::size_t m = 0; m < names.size(); ++m) {
      if (s.calibrated_materials.empty() || s.calibrated_materials[m])
        shear_to_normal_ratio(scenario.bond_materials[m]);
    }
  }
  // The strength tests' scenarios are read (and refused) before the folder is claimed.
  const std::optional<StrengthScenarios> tests =
      strength ? std::optional(load_strength_scenarios(scenario, o.strength)) : std::nullopt;
  OutputFolder folder(o.out_dir, "calibrate",
                      {"calibration.json", "calibrated.yaml", "calibrated_disc.yaml"}, o.overwrite);
  log_settings(o);
  folder.run([&] {
    std::vector<BondMaterial> answer = scenario.bond_materials;
    nlohmann::json json = {{"scenario", o.scenario}, {"stages", nlohmann::json::array()}};
    if (elastic_targets > 0) json = calibrate(o, scenario, s, answer, sample, folder);
    if (tests)
      json["strength"] = calibrate_strengths(o.scenario, *tests, o.strength, answer,
                                             o.target_nu.has_value(), folder, json);
    json.erase("stages");  // summary.json: the answer; calibration.json has every stage
    return json;
  });
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "calibrate", "find the bond parameters for a target Young's modulus (and Poisson's ratio)");
  auto o = std::make_shared<Options>();
  add_stiffness_options(cmd, *o, "out/calibrate");
  cmd->add_option("--target-E", o->target_E,
                  "target Young's modulus of the body, Pa, from the strains of its middle third "
                  "(strain gauges)");
  cmd->add_option("--target-nu", o->target_nu,
                  "target Poisson's ratio of the body (strain gauges); calibrates k_s/k_n through "
                  "kappa (pbm) or "
                  "shear_coefficient (obermayr)");
  cmd->add_option("--target-K", o->target_K,
                  "target platen stiffness K, N/m (Jarolin's: force over platen travel)");
  cmd->add_option("--target-platen-E", o->target_platen_E,
                  "target K l / A, Pa (K from the platens' travel)");
  add_strength_options(cmd, o->strength);
  cmd->add_option("--stages", o->stages,
                  "methods in order, each starting from the last one's answer (docs/validation.md "
                  "has each one's "
                  "error against the DEM): dsm, dsm-nonlinear, ste (a first guess), dsm-kinematic")
      ->capture_default_str();
  cmd->add_option("--materials", o->materials,
                  "calibrate only these bond materials (default: all, ratios fixed)");
  cmd->add_flag("--confirm-dem", o->confirm_dem,
                "finish with the explicit DEM (the default): its error at the fast answer, then "
                "one corrected run");
  cmd->add_flag(
      "--no-dem", o->no_dem,
      "stop at the fast answer (seconds instead of two DEM runs; its expected error is printed)");
  cmd->add_option("--dem", o->dem, "the DEM of the DEM stage: dem (platens) or dem-kinematic")
      ->capture_default_str();
  cmd->add_option("--calibration-tolerance", o->calibration_tolerance,
                  "stop a stage at |E/E_target - 1| below this")
      ->capture_default_str();
  cmd->add_option("--nu-tolerance", o->nu_tolerance, "and at |nu - nu_target| below this")
      ->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace bpm::cli
