#include "calibrate/calibration.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "calibrate/bond_youngs_modulus.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

/// The bond moduli a calibration may try, as multiples of the scenario's.
constexpr double kMinScale = 1e-4, kMaxScale = 1e4;

}  // namespace

CalibrationResult calibrate_bond_youngs_modulus(const Model& model, const std::vector<BondMaterial>& materials,
                                                const CalibrationSettings& s) {
  if (!(s.target_stiffness > 0.0)) throw InputError("calibrate", "the target stiffness must be > 0", "");
  std::vector<bool> chosen = s.calibrated_materials;
  if (chosen.empty()) chosen.assign(materials.size(), true);
  const std::vector<double> start = bond_youngs_moduli(materials);
  auto moduli_at = [&](double scale) {
    std::vector<double> e = start;
    for (std::size_t m = 0; m < e.size(); ++m) {
      if (chosen[m]) e[m] *= scale;
    }
    return e;
  };

  Model work = model;
  std::vector<BondMaterial> work_materials = materials;
  auto stiffness_at = [&](StiffnessMethod method, double scale) {
    set_bond_youngs_moduli(work, work_materials, moduli_at(scale), s.bond_damping);
    return estimate_sample_stiffness(work, method, s.stiffness).stiffness;
  };

  // The reachable range of a method: K at the extreme scales, for the error message.
  auto unreachable = [&](StiffnessMethod method, double slope) {
    const double low = stiffness_at(method, kMinScale), high = stiffness_at(method, kMaxScale);
    if (s.target_stiffness > low && s.target_stiffness < high) {
      return InputError("calibrate", fmt::format("{} did not reach K = {:.6g} N/m in {} evaluations: K depends too weakly "
                                                 "on E_b here (d ln K / d ln E_b = {:.3f})",
                                                 to_string(method), s.target_stiffness, s.max_evaluations, slope),
                        "the contacts carry the load, so E_b is a poor parameter for this target; a looser "
                        "--calibration-tolerance gives the best E_b found");
    }
    const bool above = s.target_stiffness > high;
    return InputError("calibrate", fmt::format("the target K = {:.6g} N/m is out of the range {} reaches: K = {:.6g} N/m at "
                                               "E_b x {:g} to {:.6g} N/m at E_b x {:g} of the scenario's",
                                               s.target_stiffness, to_string(method), low, kMinScale, high, kMaxScale),
                      above ? "the platen contacts (and particle contacts) in series with the bonds bound K from above: "
                              "stiffer platen or particle contact materials raise the limit; check the target's units"
                            : "E_b is searched within 1e-4 to 1e4 times the scenario's, and particle contacts acting "
                              "without bonds bound K from below; start from a closer E_b and check the target's units");
  };

  CalibrationResult result;
  double scale = 1.0;
  double slope = 1.0;  // d ln K / d ln s; exactly 1 for bonds alone
  bool slope_measured = false;
  bool fast_slope = false;  // a fast stage measured the slope (kept across stages)
  auto is_dem = [](StiffnessMethod m) { return m == StiffnessMethod::dem || m == StiffnessMethod::dem_kinematic; };
  auto run_stage = [&](StiffnessMethod method, bool last) {
    const double start_scale = scale;
    const auto begin = std::chrono::steady_clock::now();
    const bool dem = is_dem(method);
    if (!dem) slope_measured = false;  // the sensitivity is the last fast method's own
    const int budget = dem ? s.dem_evaluations : s.max_evaluations;
    CalibrationStage stage;
    stage.method = method;
    double k = stiffness_at(method, scale);
    ++stage.evaluations;
    stage.start_error = k / s.target_stiffness - 1.0;
    while (std::abs(k / s.target_stiffness - 1.0) > s.tolerance && stage.evaluations < budget) {
      if (!(k > 0.0)) throw InputError("calibrate", "the sample has no stiffness at this bond Young's modulus", "check the structure and the platens");
      const double previous_scale = scale, previous_k = k;
      // Steps of at most x100 within [kMinScale, kMaxScale]: a target beyond the method's range
      // drives the secant to the bound instead of to a singular or overflowing model.
      const double step = std::clamp(std::pow(s.target_stiffness / k, 1.0 / slope), 1e-2, 1e2);
      scale = std::clamp(scale * step, kMinScale, kMaxScale);
      if (scale == previous_scale) break;
      k = stiffness_at(method, scale);
      ++stage.evaluations;
      const double measured = std::log(k / previous_k) / std::log(scale / previous_scale);
      if (std::isfinite(measured)) {
        slope = std::clamp(measured, 0.02, 2.0);
        slope_measured = slope_measured || !dem;
        fast_slope = fast_slope || !dem;
      }
    }
    // Not converged and at a bound or no longer moving: the target lies beyond what the method
    // reaches. The last stage's answer would be wrong: an error. An earlier stage (a first guess)
    // is recorded as not reached, and the next starts where this one started.
    const bool stuck = scale == kMinScale || scale == kMaxScale || slope < 0.05;
    if (!dem && std::abs(k / s.target_stiffness - 1.0) > 10.0 * s.tolerance && stuck) {
      if (last) throw unreachable(method, slope);
      stage.reached = false;
      scale = start_scale;
      slope = 1.0;
      slope_measured = false;
    }
    stage.youngs_moduli = moduli_at(scale);
    stage.stiffness = k;
    stage.error = k / s.target_stiffness - 1.0;
    stage.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    result.stages.push_back(stage);
  };

  // The sensitivity d ln K / d ln E_b of the last fast method at its answer, before any DEM stage:
  // the secant of its last two evaluations, or (a stage that started at its answer, so measured
  // nothing) of one more at 1.05 times it. A DEM stage steps with it. With no DEM stage it only
  // converts K's error into E_b's, so an earlier fast stage's secant serves: on the 1e5 cylinder
  // the extra nonlinear evaluation was 27 of the 75 s of `calibrate --no-dem`.
  auto measure_sensitivity = [&](bool dem_follows) {
    if (result.sensitivity > 0.0 || result.stages.empty() || is_dem(result.stages.back().method)) return;
    if (!slope_measured && (dem_follows || !fast_slope)) {
      const double k = stiffness_at(result.stages.back().method, 1.05 * scale);
      slope = std::clamp(std::log(k / result.stages.back().stiffness) / std::log(1.05), 0.02, 2.0);
    }
    result.sensitivity = slope;
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
  result.youngs_moduli = result.stages.empty() ? start : result.stages.back().youngs_moduli;
  return result;
}

}  // namespace bpm
