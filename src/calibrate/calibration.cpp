#include "calibrate/calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "calibrate/bond_youngs_modulus.hpp"
#include "core/error.hpp"

namespace bpm {

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

  CalibrationResult result;
  double scale = 1.0;
  double slope = 1.0;  // d ln K / d ln s; exactly 1 for bonds alone
  for (const StiffnessMethod method : s.stages) {
    const auto begin = std::chrono::steady_clock::now();
    const bool dem = method == StiffnessMethod::dem || method == StiffnessMethod::dem_kinematic;
    const int budget = dem ? s.dem_evaluations : s.max_evaluations;
    CalibrationStage stage;
    stage.method = method;
    double k = stiffness_at(method, scale);
    ++stage.evaluations;
    double previous_scale = scale, previous_k = k;
    while (std::abs(k / s.target_stiffness - 1.0) > s.tolerance && stage.evaluations < budget) {
      if (!(k > 0.0)) throw InputError("calibrate", "the sample has no stiffness at this bond Young's modulus", "check the structure and the platens");
      previous_scale = scale;
      previous_k = k;
      scale *= std::pow(s.target_stiffness / k, 1.0 / slope);
      k = stiffness_at(method, scale);
      ++stage.evaluations;
      const double measured = std::log(k / previous_k) / std::log(scale / previous_scale);
      if (std::isfinite(measured)) slope = std::clamp(measured, 0.2, 2.0);
    }
    stage.youngs_moduli = moduli_at(scale);
    stage.stiffness = k;
    stage.error = k / s.target_stiffness - 1.0;
    stage.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    result.stages.push_back(stage);
  }
  result.youngs_moduli = result.stages.empty() ? start : result.stages.back().youngs_moduli;
  return result;
}

}  // namespace bpm
