#pragma once
/// Calibration of the bond parameters for a target sample (Jarolin section 5, extended to Poisson's
/// ratio): the direct stiffness method (linear, then nonlinear; the stiffness tensor estimation as
/// a first guess on request), then by default the explicit DEM: its error at the fast answer and
/// one corrected run.
///
/// The target is the body's Young's modulus E (strain gauges on the middle third,
/// compress/strain_gauge.hpp) or the platen stiffness K, and optionally the body's Poisson's ratio
/// nu. The unknowns are one scale s on the starting bond moduli (E_b,m = s E_b,m^0: one scale with
/// the ratios between materials fixed, or only the materials chosen) and, for nu, one scale t on
/// the starting shear-to-normal ratios k_s / k_n (calibrate/bond_parameters.hpp).
///
/// The search is Broyden's method on ln(E / E_target) (or ln(K / K_target)) and nu - nu_target
/// over (ln s, ln t); with E alone it is the secant in log-log. For a bond-only sample E and K are
/// proportional to E_b (every stiffness in Chen Table 9 is) and nu depends on k_s / k_n alone, so
/// the starting Jacobian [[1, .], [0, .]] is exact in its first column; the second is measured by
/// one difference in t. Contacts or walls in series only bend the lines.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bonds/bond_material.hpp"
#include "calibrate/stiffness_methods.hpp"

namespace bpm {

/// What the target E (or K) is: the body's E from its middle third's strains, as a laboratory's
/// strain gauges measure it, or the platen stiffness K (Jarolin's, including the platen contacts).
enum class CalibrationQuantity { youngs_modulus, stiffness };

struct CalibrationSettings {
  CalibrationQuantity quantity = CalibrationQuantity::youngs_modulus;
  double target = 0.0;                          ///< the body's E (Pa) or K (N/m)
  std::optional<double> target_poissons_ratio;  ///< the body's nu; calibrated through k_s / k_n
  /// The fast stages (docs/validation.md): the linear DSM with its platen walls, then the nonlinear
  /// DSM from its answer, the method with the smallest measured error against the DEM with platens
  /// (within 1 % on every bond-dominated case 1 sample).
  std::vector<StiffnessMethod> stages{StiffnessMethod::dsm, StiffnessMethod::dsm_nonlinear};
  /// Finish with the explicit DEM (`dem_method`), unless the stages list it: its error at the fast
  /// answer, then one Newton step with the fast method's Jacobian and a run there. The fast answer
  /// alone misses the true E_b by up to 3.4 % on the contact-dominated agglomerates of the
  /// validation (their K error of up to 1.4 % over a d ln K / d ln E_b of 0.4-0.6); the step lands
  /// within 0.5 % on all 24 samples, cases 1 and 2 (docs/validation.md).
  bool finish_with_dem = true;
  StiffnessMethod dem_method = StiffnessMethod::dem;
  std::vector<bool> calibrated_materials;  ///< per bond material; empty: all (one common scale)
  double tolerance = 1e-3;                 ///< stop a stage at |E / E_target - 1| below this
  double poissons_ratio_tolerance = 1e-3;  ///< and |nu - nu_target| below this
  int max_evaluations = 8;                 ///< per stage
  int dem_evaluations = 2;                 ///< DEM stages: confirm, then one corrected run
  double bond_damping = 0.0;               ///< eta_b of the scenario (bond damping depends on k)
  /// Set (the scenario's integrator.time_step is `auto`): a DEM stage runs at this safety factor
  /// times the stability limit of the model at hand, as the scenario would derive it for the
  /// calibrated bonds; unset, at the settings' step (stiffer bonds may need a shorter one).
  std::optional<double> time_step_safety;
  StiffnessSettings stiffness;
};

/// What a method measures at one set of bond parameters.
struct CalibrationMeasurement {
  double stiffness = 0.0;       ///< K, N/m
  double youngs_modulus = 0.0;  ///< the body's E, Pa (0 where the method has no strain gauges)
  double poissons_ratio = 0.0;  ///< the body's nu
};

struct CalibrationStage {
  StiffnessMethod method = StiffnessMethod::ste;
  std::vector<double> youngs_moduli;           ///< E_b per material at the stage's end, Pa
  std::vector<double> shear_to_normal_ratios;  ///< k_s / k_n per material there
  CalibrationMeasurement measured;             ///< by the stage's own method, at its answer
  double error = 0.0;                          ///< E / E_target - 1 (or K / K_target - 1)
  double poissons_ratio_error = 0.0;           ///< nu - nu_target (0 without a nu target)
  /// The errors at the stage's first evaluation, i.e. at the previous stage's answer (for a DEM
  /// stage: the DEM's own error for the answer of the fast method before it).
  double start_error = 0.0;
  double start_poissons_ratio_error = 0.0;
  int evaluations = 0;
  double seconds = 0.0;
  /// False when the method could not reach the target (only an earlier stage, a first guess: the
  /// next stage then starts from this one's start).
  bool reached = true;
};

/// The body's nu a packing reaches by k_s / k_n alone, at the starting E_b, by one method.
struct PoissonsRatioRange {
  StiffnessMethod method = StiffnessMethod::dsm;
  double low = 0.0;   ///< at k_s / k_n = kMaxShearToNormalRatio
  double high = 0.0;  ///< at k_s / k_n = kMinShearToNormalRatio
};

struct CalibrationResult {
  std::vector<CalibrationStage> stages;
  std::vector<double> youngs_moduli;           ///< the last stage's
  std::vector<double> shear_to_normal_ratios;  ///< the last stage's
  /// d ln E / d ln E_b (or d ln K / d ln E_b) by the last fast method near its answer (the secant
  /// of its last two evaluations, or of one more at 1.05 times the answer's E_b; with no DEM stage
  /// to step with it, an earlier fast stage's secant instead of that evaluation); 0 if no fast
  /// stage ran.
  double sensitivity = 0.0;
  /// With a nu target: the last fast method's Jacobian at its answer, rows (ln E, nu), columns
  /// (ln s, ln t); and the range of nu checked before the search.
  std::optional<std::array<double, 4>> jacobian;
  std::optional<PoissonsRatioRange> poissons_ratio_range;
};

std::string_view to_string(CalibrationQuantity quantity);

/// `materials` are the scenario's bond materials (their E_b and k_s / k_n are the starting
/// values); `model` is at its initial state. Neither is changed. A target the method cannot reach
/// throws InputError with the reachable range: for K, measured at E_b scaled by 1e-4 and 1e4 (the
/// platen contacts in series bound K from above, particle contacts acting without bonds bound it
/// from below); for nu, measured at the bounds of k_s / k_n before the search.
CalibrationResult calibrate_bond_parameters(const Model& model,
                                            const std::vector<BondMaterial>& materials,
                                            const CalibrationSettings& settings);

}  // namespace bpm
