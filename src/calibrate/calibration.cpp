#include "calibrate/calibration.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "calibrate/bond_parameters.hpp"
#include "calibrate/broyden.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

/// The bond moduli a calibration may try, as multiples of the scenario's.
constexpr double kMinScale = 1e-4, kMaxScale = 1e4;
/// d nu / d ln t is negative (a stiffer shear holds the sides in: nu = 0.32 to -0.57 as k_s / k_n
/// goes from 0.01 to 10 on the small cylinder); kept below this so that a step always moves t.
constexpr double kMaxShearSlope = -1e-3;

bool is_dem(StiffnessMethod m) {
  return m == StiffnessMethod::dem || m == StiffnessMethod::dem_kinematic;
}

/// The unknowns: ln s (E_b = s E_b^0) and ln t (k_s / k_n = t (k_s / k_n)^0).
struct Point {
  double log_scale = 0.0, log_shear = 0.0;
};

}  // namespace

std::string_view to_string(CalibrationQuantity quantity) {
  return quantity == CalibrationQuantity::stiffness ? "K" : "E";
}

CalibrationResult calibrate_bond_parameters(const Model& model,
                                            const std::vector<BondMaterial>& materials,
                                            const CalibrationSettings& s) {
  if (!(s.target > 0.0)) throw InputError("calibrate", "the target E or K must be > 0", "");
  const bool fit_nu = s.target_poissons_ratio.has_value();
  if (fit_nu && !(*s.target_poissons_ratio > -1.0 && *s.target_poissons_ratio < 0.5)) {
    throw InputError(
        "--target-nu",
        fmt::format("a Poisson's ratio must lie in (-1, 0.5), got {}", *s.target_poissons_ratio),
        "give the body's nu from the datasheet");
  }
  const bool by_stiffness = s.quantity == CalibrationQuantity::stiffness;
  const std::string_view symbol = to_string(s.quantity);
  const char* unit = by_stiffness ? "N/m" : "Pa";
  std::vector<bool> chosen = s.calibrated_materials;
  if (chosen.empty()) chosen.assign(materials.size(), true);
  const std::vector<double> start = bond_youngs_moduli(materials);
  std::vector<double> start_ratio(materials.size(), 0.0);
  // The common shear scale t keeps every chosen material's k_s / k_n within the searched bounds.
  double min_log_shear = 0.0, max_log_shear = 0.0;
  if (fit_nu) {
    min_log_shear = -1e300, max_log_shear = 1e300;
    for (std::size_t m = 0; m < materials.size(); ++m) {
      if (!chosen[m]) continue;
      start_ratio[m] = shear_to_normal_ratio(materials[m]);
      min_log_shear = std::max(min_log_shear, std::log(kMinShearToNormalRatio / start_ratio[m]));
      max_log_shear = std::min(max_log_shear, std::log(kMaxShearToNormalRatio / start_ratio[m]));
    }
    if (!(min_log_shear < 0.0 && max_log_shear > 0.0)) {
      throw InputError("bond_materials",
                       "a starting k_s / k_n lies outside the searched 0.01 to 10",
                       "start from kappa (or alpha_s) nearer the model's default");
    }
  }

  Model work = model;
  std::vector<BondMaterial> work_materials = materials;
  auto apply = [&](const Point& x) {
    for (std::size_t m = 0; m < work_materials.size(); ++m) {
      if (!chosen[m]) continue;
      work_materials[m].youngs_modulus = start[m] * std::exp(x.log_scale);
      if (fit_nu)
        set_shear_to_normal_ratio(work_materials[m], start_ratio[m] * std::exp(x.log_shear));
    }
    rederive_bond_stiffness(work, work_materials, s.bond_damping);
  };
  StiffnessSettings settings = s.stiffness;
  auto measure = [&](StiffnessMethod method, const Point& x) {
    apply(x);
    if (s.time_step_safety && is_dem(method)) {
      settings.compression.time_step =
          scenario_time_step(work, settings.compression.mass_scaling, *s.time_step_safety);
    }
    const StiffnessEstimate e = estimate_sample_stiffness(work, method, settings);
    if ((!by_stiffness || fit_nu) && !e.body.valid) {
      throw InputError(
          "calibrate",
          fmt::format("{} does not measure the body's E and nu (strain gauges on the middle third)",
                      to_string(method)),
          "use dsm, dsm-nonlinear, ste or dem, or aim at the platen stiffness (--target-K, "
          "--target-platen-E)");
    }
    return CalibrationMeasurement{e.stiffness, e.body.youngs_modulus, e.body.poissons_ratio};
  };
  auto value = [&](const CalibrationMeasurement& m) {
    return by_stiffness ? m.stiffness : m.youngs_modulus;
  };
  auto error = [&](const CalibrationMeasurement& m) { return value(m) / s.target - 1.0; };
  auto nu_error = [&](const CalibrationMeasurement& m) {
    return fit_nu ? m.poissons_ratio - *s.target_poissons_ratio : 0.0;
  };
  auto converged = [&](const CalibrationMeasurement& m) {
    return std::abs(error(m)) <= s.tolerance && std::abs(nu_error(m)) <= s.poissons_ratio_tolerance;
  };
  // The residual: ln(E / E_target) and nu - nu_target.
  auto residual = [&](const CalibrationMeasurement& m) {
    return std::array<double, 2>{std::log(value(m) / s.target), nu_error(m)};
  };

  // The reachable range of E (or K) of a method: at the extreme scales, for the error message.
  auto unreachable = [&](StiffnessMethod method, const Point& at, double slope) {
    const double low = value(measure(method, {std::log(kMinScale), at.log_shear}));
    const double high = value(measure(method, {std::log(kMaxScale), at.log_shear}));
    if (s.target > low && s.target < high) {
      return InputError(
          "calibrate",
          fmt::format("{} did not reach {} = {:.6g} {} in {} evaluations: {} depends too weakly "
                      "on E_b here (d ln {} / d ln E_b = {:.3f})",
                      to_string(method), symbol, s.target, unit, s.max_evaluations, symbol, symbol,
                      slope),
          "the contacts carry the load, so E_b is a poor parameter for this target; a looser "
          "--calibration-tolerance gives the best E_b found");
    }
    const bool above = s.target > high;
    return InputError(
        "calibrate",
        fmt::format("the target {} = {:.6g} {} is out of the range {} reaches: {} = {:.6g} {} at "
                    "E_b x {:g} to {:.6g} {} at E_b x {:g} of the scenario's",
                    symbol, s.target, unit, to_string(method), symbol, low, unit, kMinScale, high,
                    unit, kMaxScale),
        above ? "the platen contacts (and particle contacts) in series with the bonds bound K from "
                "above: "
                "stiffer platen or particle contact materials raise the limit; check the target's "
                "units"
              : "E_b is searched within 1e-4 to 1e4 times the scenario's, and particle contacts "
                "acting "
                "without bonds bound it from below; start from a closer E_b and check the target's "
                "units");
  };

  CalibrationResult result;
  Point x;
  // The starting Jacobian: d ln E / d ln s = 1 exactly for bonds alone; nu does not depend on s
  // there; the nu column is measured before the first step.
  Jacobian2 jacobian{1.0, 0.0, 0.0, 0.0};  // rows (ln E, nu), columns (ln s, ln t)
  bool shear_column_known = false;
  bool slope_measured = false;  // the last fast stage measured d ln E / d ln s itself
  bool fast_slope = false;      // a fast stage measured it (kept across stages)

  if (fit_nu) {
    // The range of nu by k_s / k_n alone, by the first method that measures it well (the STE's nu
    // is 0.05-0.31 low on the validation samples).
    StiffnessMethod method = s.stages.empty() ? s.dem_method : s.stages.front();
    for (const StiffnessMethod m : s.stages) {
      if (m != StiffnessMethod::ste) {
        method = m;
        break;
      }
    }
    PoissonsRatioRange range{method, measure(method, {0.0, max_log_shear}).poissons_ratio,
                             measure(method, {0.0, min_log_shear}).poissons_ratio};
    result.poissons_ratio_range = range;
    const double nu = *s.target_poissons_ratio;
    if (!(nu >= range.low && nu <= range.high)) {
      throw InputError(
          "--target-nu",
          fmt::format(
              "the target nu = {:.4g} is out of the range this packing reaches by k_s / k_n: nu = "
              "{:.4g} at k_s / k_n = {:g} to {:.4g} at k_s / k_n = {:g} (by {}, at the scenario's "
              "E_b)",
              nu, range.low, kMaxShearToNormalRatio, range.high, kMinShearToNormalRatio,
              to_string(method)),
          "a bonded packing's nu is set by its coordination and the bonds' shear-to-normal ratio: "
          "a "
          "packing with more or fewer bonds per particle, or contacts beside the bonds, moves the "
          "range");
    }
  }

  auto run_stage = [&](StiffnessMethod method, bool last) {
    const Point start_point = x;
    const auto begin = std::chrono::steady_clock::now();
    const bool dem = is_dem(method);
    if (!dem) slope_measured = false;  // the sensitivity is the last fast method's own
    const int budget = dem ? s.dem_evaluations : s.max_evaluations;
    CalibrationStage stage;
    stage.method = method;
    CalibrationMeasurement m = measure(method, x);
    ++stage.evaluations;
    stage.start_error = error(m);
    stage.start_poissons_ratio_error = nu_error(m);
    if (fit_nu && !shear_column_known && !converged(m)) {
      // The nu column by one difference: t x 1.25.
      constexpr double h = 0.22314355131420976;  // ln 1.25
      const CalibrationMeasurement d = measure(method, {x.log_scale, x.log_shear + h});
      ++stage.evaluations;
      jacobian[1] = std::log(value(d) / value(m)) / h;
      jacobian[3] = std::min((d.poissons_ratio - m.poissons_ratio) / h, kMaxShearSlope);
      shear_column_known = true;
    }
    bool shear_stuck = false;
    while (!converged(m) && stage.evaluations < budget) {
      if (!(value(m) > 0.0)) {
        throw InputError("calibrate", "the sample has no stiffness at these bond parameters",
                         "check the structure and the platens");
      }
      const std::array<double, 2> f = residual(m);
      // The Newton step J dx = -f; steps of at most x100 in E_b and x10 in k_s / k_n within their
      // bounds: a target beyond the method's range drives the search to a bound instead of to a
      // singular or overflowing model.
      const auto [step_scale, step_shear] = newton_step(jacobian, f, fit_nu, 1e-12);
      const Point previous = x;
      x.log_scale = std::clamp(x.log_scale + std::clamp(step_scale, -std::log(1e2), std::log(1e2)),
                               std::log(kMinScale), std::log(kMaxScale));
      x.log_shear = std::clamp(x.log_shear + std::clamp(step_shear, -std::log(1e1), std::log(1e1)),
                               min_log_shear, max_log_shear);
      shear_stuck = fit_nu && (x.log_shear == min_log_shear || x.log_shear == max_log_shear);
      if (x.log_scale == previous.log_scale && x.log_shear == previous.log_shear) break;
      const CalibrationMeasurement next = measure(method, x);
      ++stage.evaluations;
      // Broyden's update: with E alone the secant slope.
      const std::array<double, 2> g = residual(next);
      const double dx0 = x.log_scale - previous.log_scale, dx1 = x.log_shear - previous.log_shear;
      if (broyden_update(jacobian, {dx0, dx1}, {g[0] - f[0], g[1] - f[1]})) {
        jacobian[0] = std::clamp(jacobian[0], 0.02, 2.0);
        jacobian[3] = std::min(jacobian[3], kMaxShearSlope);
        if (dx0 != 0.0) {
          slope_measured = slope_measured || !dem;
          fast_slope = fast_slope || !dem;
        }
      }
      m = next;
    }
    // Not converged and at a bound or no longer moving: the target lies beyond what the method
    // reaches. The last stage's answer would be wrong: an error. An earlier stage (a first guess)
    // is recorded as not reached, and the next starts where this one started.
    const bool e_stuck = x.log_scale == std::log(kMinScale) || x.log_scale == std::log(kMaxScale) ||
                         jacobian[0] < 0.05;
    const bool far = std::abs(error(m)) > 10.0 * s.tolerance ||
                     std::abs(nu_error(m)) > 10.0 * s.poissons_ratio_tolerance;
    if (!dem && far && (e_stuck || shear_stuck)) {
      if (last) {
        if (e_stuck) throw unreachable(method, x, jacobian[0]);
        throw InputError(
            "--target-nu",
            fmt::format(
                "{} did not reach nu = {:.4g}: k_s / k_n reached its bound with nu = {:.4g}",
                to_string(method), *s.target_poissons_ratio, m.poissons_ratio),
            "the range of nu moves with E_b where contacts carry load; a nu nearer the range "
            "printed by "
            "calibration.json's poissons_ratio_range is reachable");
      }
      stage.reached = false;
      x = start_point;
      jacobian = {1.0, 0.0, 0.0, 0.0};
      shear_column_known = false;
      slope_measured = false;
    }
    for (std::size_t k = 0; k < materials.size(); ++k) {
      stage.youngs_moduli.push_back(chosen[k] ? start[k] * std::exp(x.log_scale) : start[k]);
      if (fit_nu)
        stage.shear_to_normal_ratios.push_back(chosen[k] ? start_ratio[k] * std::exp(x.log_shear)
                                                         : 0.0);
    }
    stage.measured = m;
    stage.error = error(m);
    stage.poissons_ratio_error = nu_error(m);
    stage.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    result.stages.push_back(stage);
  };

  // The Jacobian of the last fast method at its answer, before any DEM stage. With E alone: the
  // secant of its last two evaluations, or (a stage that started at its answer, so measured
  // nothing) of one more at 1.05 times it. A DEM stage steps with it. With no DEM stage it only
  // converts E's error into E_b's, so an earlier fast stage's secant serves: on the 1e5 cylinder
  // the extra nonlinear evaluation was 27 of the 75 s of `calibrate --no-dem`. With nu, a DEM
  // stage steps with differences in both unknowns at the answer (Broyden's Jacobian is only
  // good along the path it took).
  auto measure_sensitivity = [&](bool dem_follows) {
    if (result.sensitivity > 0.0 || result.stages.empty() || is_dem(result.stages.back().method))
      return;
    const CalibrationStage& last = result.stages.back();
    constexpr double h = 0.04879016416943205;  // ln 1.05
    if (fit_nu && dem_follows) {
      const CalibrationMeasurement ds = measure(last.method, {x.log_scale + h, x.log_shear});
      const CalibrationMeasurement dt = measure(last.method, {x.log_scale, x.log_shear + 2.0 * h});
      jacobian = {std::log(value(ds) / value(last.measured)) / h,
                  std::log(value(dt) / value(last.measured)) / (2.0 * h),
                  (ds.poissons_ratio - last.measured.poissons_ratio) / h,
                  (dt.poissons_ratio - last.measured.poissons_ratio) / (2.0 * h)};
      jacobian[0] = std::clamp(jacobian[0], 0.02, 2.0);
      jacobian[3] = std::min(jacobian[3], kMaxShearSlope);
    } else if (!slope_measured && (dem_follows || !fast_slope)) {
      const CalibrationMeasurement d = measure(last.method, {x.log_scale + h, x.log_shear});
      jacobian[0] = std::clamp(std::log(value(d) / value(last.measured)) / h, 0.02, 2.0);
    }
    result.sensitivity = jacobian[0];
    if (fit_nu) result.jacobian = jacobian;
  };
  bool listed_dem = false;
  for (std::size_t index = 0; index < s.stages.size(); ++index) {
    if (is_dem(s.stages[index])) {
      measure_sensitivity(true);
      listed_dem = true;
    }
    run_stage(s.stages[index], index + 1 == s.stages.size());
  }
  measure_sensitivity(!listed_dem && s.finish_with_dem);
  if (!listed_dem && s.finish_with_dem) run_stage(s.dem_method, true);
  if (result.stages.empty()) {
    result.youngs_moduli = start;
    if (fit_nu) result.shear_to_normal_ratios = start_ratio;
  } else {
    result.youngs_moduli = result.stages.back().youngs_moduli;
    result.shear_to_normal_ratios = result.stages.back().shear_to_normal_ratios;
  }
  return result;
}

}  // namespace bpm
