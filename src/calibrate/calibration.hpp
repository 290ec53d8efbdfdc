#pragma once
/// Calibration of the bond Young's modulus for a target sample stiffness (Jarolin section 5):
/// the direct stiffness method (linear, then nonlinear; the stiffness tensor estimation as a first
/// guess on request), then by default the explicit DEM: its error at the fast answer and one
/// corrected run. Every stage searches one scale factor s on
/// the starting moduli (E_b,m = s E_b,m^0: one scale with the ratios between materials fixed, or
/// only the materials chosen), so the calibration stays one-dimensional as in Jarolin section 2.
///
/// The search is a secant iteration in log-log: K is proportional to E_b for a bond-only sample
/// (every stiffness in Chen Table 9 is), so the first step s K_target / K(s) is exact there, and
/// contacts or walls in series only bend the line; the slope d ln K / d ln s is re-estimated from
/// the last two evaluations. Each stage starts from the previous stage's scale.
#include <string>
#include <vector>

#include "bonds/bond_material.hpp"
#include "calibrate/stiffness_methods.hpp"

namespace bpm {

struct CalibrationSettings {
  double target_stiffness = 0.0;  ///< K, N/m
  /// The fast stages (docs/validation.md): the linear DSM with its platen walls, then the nonlinear
  /// DSM from its answer, the method with the smallest measured error against the DEM with platens
  /// (within 1 % on every bond-dominated case 1 sample).
  std::vector<StiffnessMethod> stages{StiffnessMethod::dsm, StiffnessMethod::dsm_nonlinear};
  /// Finish with the explicit DEM (`dem_method`), unless the stages list it: its error at the fast
  /// answer, then one secant step with the fast method's d ln K / d ln E_b and a run there. The
  /// fast answer alone misses the true E_b by up to 3.4 % on the contact-dominated agglomerates of
  /// the validation (their K error of up to 1.4 % over a d ln K / d ln E_b of 0.4-0.6); the step
  /// lands within 0.5 % on all 24 samples, cases 1 and 2 (docs/validation.md).
  bool finish_with_dem = true;
  StiffnessMethod dem_method = StiffnessMethod::dem;
  std::vector<bool> calibrated_materials;  ///< per bond material; empty: all (one common scale)
  double tolerance = 1e-3;        ///< stop a stage at |K / K_target - 1| below this
  int max_evaluations = 8;        ///< per stage
  int dem_evaluations = 2;        ///< DEM stages: confirm, then one corrected run
  double bond_damping = 0.0;      ///< eta_b of the scenario (bond damping depends on k)
  StiffnessSettings stiffness;
};

struct CalibrationStage {
  StiffnessMethod method = StiffnessMethod::ste;
  std::vector<double> youngs_moduli;  ///< E_b per material at the stage's end, Pa
  double stiffness = 0.0;             ///< K at those moduli, N/m
  double error = 0.0;                 ///< K / K_target - 1, K by the stage's own method
  /// K / K_target - 1 at the stage's first evaluation, i.e. at the previous stage's answer (for a
  /// DEM stage: the DEM's own error for the answer of the fast method before it).
  double start_error = 0.0;
  int evaluations = 0;
  double seconds = 0.0;
  /// False when the method could not reach the target (only an earlier stage, a first guess: the
  /// next stage then starts from this one's start).
  bool reached = true;
};

struct CalibrationResult {
  std::vector<CalibrationStage> stages;
  std::vector<double> youngs_moduli;  ///< the last stage's
  /// d ln K / d ln E_b by the last fast method near its answer (the secant of its last two
  /// evaluations, or of one more at 1.05 times the answer's E_b; with no DEM stage to step with
  /// it, an earlier fast stage's secant instead of that evaluation); 0 if no fast stage ran.
  double sensitivity = 0.0;
};

/// `materials` are the scenario's bond materials (their E_b are the starting values); `model` is
/// at its initial state. Neither is changed. A target the method cannot reach (the platen contacts
/// in series bound K from above, particle contacts acting without bonds bound it from below)
/// throws InputError with the reachable range, measured at E_b scaled by 1e-4 and 1e4.
CalibrationResult calibrate_bond_youngs_modulus(const Model& model, const std::vector<BondMaterial>& materials,
                                                const CalibrationSettings& settings);

}  // namespace bpm
