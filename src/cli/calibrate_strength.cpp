#include "cli/calibrate_strength.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "calibrate/bond_parameters.hpp"
#include "calibrate/first_break.hpp"
#include "calibrate/strength_calibration.hpp"
#include "core/error.hpp"
#include "io/log.hpp"
#include "scenario/calibrated_scenario.hpp"

namespace bpm::cli {
namespace {

void require_to_failure(const Scenario& s, const std::string& path, const char* strength) {
  if (!s.compression || s.compression->failure_drop <= 0.0) {
    throw InputError(
        path + ": compression.failure_drop",
        fmt::format("is missing: the {} is read at the peak, so the test must run past it",
                    strength),
        "add failure_drop: 0.5 and max_strain (e.g. 25 times target_strain)");
  }
  if (!s.model.bonds.breakable) {
    throw InputError(path + ": bond_materials", "no bond can break, so the test has no peak",
                     "give the bond materials tensile_strength and shear_strength (a first guess)");
  }
}

/// The disc's bond materials: SCENARIO's of the same name (`answer`).
std::vector<BondMaterial> disc_materials(const Scenario& disc,
                                         const std::vector<BondMaterial>& answer,
                                         const std::vector<std::string>& names) {
  std::vector<BondMaterial> materials;
  for (const std::string& name : disc.bond_material_names) {
    const auto it = std::find(names.begin(), names.end(), name);
    materials.push_back(answer[static_cast<std::size_t>(it - names.begin())]);
  }
  return materials;
}

}  // namespace

void add_strength_options(CLI::App* cmd, StrengthOptions& o) {
  cmd->add_option("--target-ucs", o.target_ucs,
                  "target uniaxial compressive strength, Pa: the bond strengths by DEM runs of "
                  "SCENARIO's test");
  cmd->add_option("--target-bts", o.target_bts,
                  "target Brazilian tensile strength, Pa (needs --disc)");
  cmd->add_option(
      "--disc", o.disc,
      "the Brazilian test's scenario (test: brazilian), with SCENARIO's bond materials");
  cmd->add_option("--strength-tolerance", o.tolerance,
                  "stop at |S/S_target - 1| below this for UCS and BTS")
      ->capture_default_str();
  cmd->add_option("--strength-evaluations", o.max_evaluations,
                  "at most this many evaluations (each: both tests)")
      ->capture_default_str();
}

StrengthScenarios load_strength_scenarios(const Scenario& scenario, const StrengthOptions& o) {
  StrengthScenarios tests{scenario, std::nullopt};
  if (o.target_ucs > 0.0) require_to_failure(scenario, scenario.path, "UCS");
  if (o.target_bts > 0.0) {
    if (o.disc.empty()) {
      throw InputError("--target-bts", "needs the Brazilian test's scenario",
                       "give --disc DISC.yaml (compression.test: brazilian; "
                       "examples/05_strength/brazilian.yaml)");
    }
    Scenario disc = load_scenario(o.disc);
    if (!disc.compression || disc.compression->test != LabTest::brazilian) {
      throw InputError(o.disc + ": compression.test", "is not brazilian",
                       "give the disc's scenario with test: brazilian");
    }
    require_to_failure(disc, o.disc, "BTS");
    for (const std::string& name : disc.bond_material_names) {
      if (std::find(scenario.bond_material_names.begin(), scenario.bond_material_names.end(),
                    name) == scenario.bond_material_names.end()) {
        throw InputError(
            o.disc + ": bond_materials." + name, "is not a bond material of " + scenario.path,
            "the disc takes the calibrated materials by name: name them as in " + scenario.path);
      }
    }
    tests.disc = std::move(disc);
  }
  if (o.tolerance <= 0.0 || o.max_evaluations < 1) {
    throw InputError("--strength-tolerance", "must be > 0, with --strength-evaluations >= 1",
                     "e.g. 0.02 and 10");
  }
  return tests;
}

nlohmann::json calibrate_strengths(const std::string& scenario_path, const StrengthScenarios& tests,
                                   const StrengthOptions& o, std::vector<BondMaterial>& answer,
                                   bool with_shear_ratio, const OutputFolder& folder,
                                   nlohmann::json& calibration) {
  const std::vector<std::string>& names = tests.cylinder.bond_material_names;
  // The tests' models with the calibrated stiffness; their strengths as drawn from the scenarios.
  Model cylinder = tests.cylinder.model;
  rederive_bond_stiffness(cylinder, answer, cylinder.damping.bond);
  std::optional<Model> disc;
  std::vector<BondMaterial> disc_answer;
  if (tests.disc) {
    disc = tests.disc->model;
    disc_answer = disc_materials(*tests.disc, answer, names);
    disc->bonds.draw_strengths(disc_answer, tests.disc->seed);
    rederive_bond_stiffness(*disc, disc_answer, disc->damping.bond);
  }
  // Each test at the step its scenario derives for the calibrated bonds (time_step: auto), as
  // `bpmkit run` of the calibrated scenario does.
  auto test_of = [](Model& model, const Scenario& scenario) {
    StrengthTest test{&model, *scenario.compression, {}, scenario.seed};
    if (!scenario.time_step_given) {
      test.settings.time_step =
          scenario_time_step(model, test.settings.mass_scaling, scenario.safety_factor);
    }
    return test;
  };
  std::optional<StrengthTest> ucs, bts;
  if (o.target_ucs > 0.0) {
    ucs = test_of(cylinder, tests.cylinder);
    ucs->materials = answer;
  }
  if (o.target_bts > 0.0) {
    bts = test_of(*disc, *tests.disc);
    bts->materials = disc_answer;
  }
  StrengthCalibrationSettings s;
  s.target_ucs = o.target_ucs;
  s.target_bts = o.target_bts;
  s.tolerance = o.tolerance;
  s.max_evaluations = o.max_evaluations;

  fmt::print("strength target:{}{} (DEM runs of the tests, each past its peak)\n",
             ucs ? fmt::format(" UCS = {:.6g} Pa", o.target_ucs) : "",
             bts ? fmt::format(" BTS = {:.6g} Pa", o.target_bts) : "");
  nlohmann::json block = {
      {"target_ucs_Pa", ucs ? nlohmann::json(o.target_ucs) : nlohmann::json(nullptr)},
      {"target_bts_Pa", bts ? nlohmann::json(o.target_bts) : nlohmann::json(nullptr)},
      {"tolerance", o.tolerance},
      {"linear_first_break", nlohmann::json::object()},
      {"evaluations", nlohmann::json::array()}};
  // The linear estimate at the scenario's strengths, set beside the first evaluation's DEM peak
  // (same strengths) when it ends.
  for (const auto& [test, key] : {std::tuple{&ucs, "ucs"}, std::tuple{&bts, "bts"}}) {
    if (!*test) continue;
    const FirstBreakEstimate first = linear_first_break(*(*test)->model, (*test)->settings);
    fmt::print(
        "linear first break ({}) at the scenario's strengths: {} = {:.6g} Pa (bond {}, {})\n",
        first.method, key == std::string("ucs") ? "UCS" : "BTS", first.stress, first.bond,
        first.mode == BreakMode::tension ? "tension" : "shear");
    block["linear_first_break"][key] = {
        {"method", first.method},
        {"estimate_Pa", first.stress},
        {"bond", first.bond},
        {"mode", first.mode == BreakMode::tension ? "tension" : "shear"}};
  }
  auto observe = [&](const StrengthEvaluation& e) {
    if (block["evaluations"].empty()) {
      for (auto& [key, first] : block["linear_first_break"].items()) {
        const double peak = strength_of(key == "ucs" ? e.ucs : e.bts);
        first["of_dem_peak"] = first["estimate_Pa"].get<double>() / peak;
        fmt::print("linear first break: {:.3g} of the DEM's {} peak at the same strengths\n",
                   first["of_dem_peak"].get<double>(), key == "ucs" ? "UCS" : "BTS");
      }
    }
    std::string text;
    nlohmann::json entry = {{"tensile_strength_scale", e.tensile_scale},
                            {"shear_strength_scale", e.shear_scale},
                            {"wall_s", e.seconds}};
    for (const auto& [result, target, key] :
         {std::tuple{&e.ucs, o.target_ucs, "ucs"}, std::tuple{&e.bts, o.target_bts, "bts"}}) {
      if (!*result) continue;
      const CompressionResult& r = **result;
      text += fmt::format(
          "  {} = {:.6g} Pa ({:+.2f} %; kinetic/elastic {:.2g}, imbalance {:.2g} at the peak)",
          key == std::string("ucs") ? "UCS" : "BTS", r.strength,
          100.0 * (r.strength / target - 1.0), r.peak_kinetic_ratio, r.peak_force_imbalance);
      entry[std::string(key) + "_Pa"] = r.strength;
      entry[std::string(key) + "_error"] = r.strength / target - 1.0;
      entry[std::string(key) + "_peak_strain"] = r.peak_strain;
      entry[std::string(key) + "_kinetic_to_elastic_at_peak"] = r.peak_kinetic_ratio;
      entry[std::string(key) + "_force_imbalance_at_peak"] = r.peak_force_imbalance;
    }
    fmt::print("strength {:>2}: sigma_t x {:.4g}, tau_s x {:.4g}:{}   {:.1f} s\n",
               block["evaluations"].size() + 1, e.tensile_scale, e.shear_scale, text, e.seconds);
    std::fflush(stdout);
    block["evaluations"].push_back(entry);
    calibration["strength"] = block;  // on disk as each evaluation ends
    folder.write("calibration.json", calibration.dump(2) + "\n");
  };
  const StrengthCalibrationResult r =
      calibrate_bond_strengths(dem_strength_evaluator(ucs, bts), s, observe);
  for (BondMaterial& m : answer) scale_strengths(m, r.tensile_scale, r.shear_scale);
  block["tensile_strength_scale"] = r.tensile_scale;
  block["shear_strength_scale"] = r.shear_scale;
  block["converged"] = r.converged;
  block["scatter"] = r.scatter;
  nlohmann::json strengths = nlohmann::json::object();
  for (std::size_t m = 0; m < answer.size(); ++m) {
    strengths[names[m]] = {{"tensile_strength_Pa", answer[m].tensile_strength.value},
                           {"shear_strength_Pa", answer[m].shear_strength.value}};
  }
  block["bond_strengths"] = strengths;
  calibration["strength"] = block;
  folder.write("calibration.json", calibration.dump(2) + "\n");
  if (r.converged) {
    fmt::print(
        "strengths: sigma_t x {:.4g}, tau_s x {:.4g} of the scenario's, within {:g} of every "
        "target\n",
        r.tensile_scale, r.shear_scale, o.tolerance);
  } else {
    const bool noise_limited =
        static_cast<int>(r.evaluations.size()) < o.max_evaluations && r.scatter > 0.0;
    fmt::print(
        "strengths: not within {:g} of the targets after {} evaluations; the closest evaluation "
        "(sigma_t x {:.4g}, tau_s x {:.4g}) is written ({})\n",
        o.tolerance, r.evaluations.size(), r.tensile_scale, r.shear_scale,
        noise_limited
            ? fmt::format("steps under 1 % in the strengths stopped improving on it; the "
                          "evaluations within 2 % of its strengths scattered by {:.1f} %: the "
                          "samples' noise, which larger samples narrow",
                          100.0 * r.scatter)
            : "--strength-evaluations allows more");
  }
  const std::string header =
      "bpmkit calibrate: " + scenario_path + " with the calibrated bond parameters and strengths";
  log::info("wrote {}\n",
            folder.write("calibrated.yaml",
                         calibrated_scenario_yaml(scenario_path, answer, with_shear_ratio, true,
                                                  folder.dir(), {header})));
  if (tests.disc) {
    for (BondMaterial& m : disc_answer) {
      const auto it = std::find(names.begin(), names.end(), m.name);
      m = answer[static_cast<std::size_t>(it - names.begin())];
    }
    log::info("wrote {}\n",
              folder.write("calibrated_disc.yaml",
                           calibrated_scenario_yaml(
                               tests.disc->path, disc_answer, with_shear_ratio, true, folder.dir(),
                               {"bpmkit calibrate: " + tests.disc->path +
                                " with the calibrated bond parameters and strengths"})));
  }
  return block;
}

}  // namespace bpm::cli
