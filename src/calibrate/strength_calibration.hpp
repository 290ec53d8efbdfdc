#pragma once
/// Calibration of the bond strengths for a target UCS and BTS (or one of them) by DEM runs of the
/// strength tests (compress/uniaxial_compression.hpp, LabTest). The unknowns are a scale a on every
/// bond's tensile strength and a scale b on every shear strength (sigma_t = a sigma_t^0, tau_s =
/// b tau_s^0); the drawn spread of the strengths is kept, scaled. With one target a = b.
///
/// The search, in x = (ln a, ln b) on the residuals ln(S / S_target):
/// 1. the scenario's strengths;
/// 2. every strength scaled by the mean correction (where the bonds alone carry a test, its peak
///    load is proportional to their strengths);
/// 3. with two targets, the tensile strengths alone x2 (or / 2) towards the target UCS / BTS;
/// 4. then steps to the zero of an affine model fitted by weighted least squares to every
///    evaluation about the best one (Levenberg-Marquardt damped, within a trust region of x2 that
///    doubles, up to x4, after a step that improved and halves after one that did not): the tests
///    are not homogeneous in the strengths where Hertz-Mindlin contacts share the load (a strength
///    scaled by 4 moved a 2,578-grain disc's BTS by 6.1), nor smooth where a few bonds set a small
///    sample's peak, and a fit over all evaluations is steadier there than Broyden's updates of one
///    Jacobian (which stalled on a start where the shear strength set both tests). The search stops
///    where the trust region falls below 1 % in the scales: closer steps on a small sample follow
///    its noise.
/// Each evaluation runs the UCS and the BTS tests side by side (two threads, each with half the
/// cores); the result is the same for any thread count.
///
/// The UCS / BTS ratio a packing produces is bounded: b / a is searched within 1/16 to 16; a target
/// ratio beyond what that reaches is refused with the range (the classic weakness of parallel
/// bonds, whose UCS / BTS stays low).
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "bonds/bond_material.hpp"
#include "compress/uniaxial_compression.hpp"
#include "model/model.hpp"

namespace bpm {

/// One strength test: its model (at the initial state) and settings (to failure), and the bond
/// materials and seed its strengths are drawn from: an evaluation draws them again from the
/// materials with scaled strengths, so that it runs exactly what the calibrated scenario runs.
struct StrengthTest {
  const Model* model = nullptr;
  UniaxialCompression settings;
  std::vector<BondMaterial> materials;
  std::uint64_t seed = 1;
};

struct StrengthEvaluation {
  double tensile_scale = 1.0;  ///< a
  double shear_scale = 1.0;    ///< b
  std::optional<CompressionResult> ucs, bts;
  double seconds = 0.0;
};

/// What one evaluation measures: UCS and BTS (0 for a test not run) at tensile and shear scales.
using StrengthEvaluator =
    std::function<StrengthEvaluation(double tensile_scale, double shear_scale)>;

struct StrengthCalibrationSettings {
  double target_ucs = 0.0;  ///< Pa; 0: not a target
  double target_bts = 0.0;  ///< Pa; 0: not a target
  double tolerance = 0.02;  ///< stop at |S / S_target - 1| below this for every target
  int max_evaluations = 10;
};

struct StrengthCalibrationResult {
  std::vector<StrengthEvaluation> evaluations;
  double tensile_scale = 1.0,
         shear_scale = 1.0;  ///< the answer: the evaluation closest to the targets
  bool converged = false;
  /// The largest relative spread of one test's strength over the evaluations within 2 % of the
  /// answer's scales (0 where none is that close): a search that stopped short of the tolerance
  /// there stopped at the sample's noise, not for want of evaluations.
  double scatter = 0.0;
};

/// Runs the tests (either may be absent: no model) at scaled strengths.
StrengthEvaluator dem_strength_evaluator(const std::optional<StrengthTest>& ucs,
                                         const std::optional<StrengthTest>& bts);

/// The search; `observer` is called after every evaluation (stream it: a DEM evaluation takes
/// minutes). Throws InputError for a UCS / BTS ratio out of reach, with the range.
StrengthCalibrationResult calibrate_bond_strengths(
    const StrengthEvaluator& evaluate, const StrengthCalibrationSettings& s,
    const std::function<void(const StrengthEvaluation&)>& observer = {});

/// Scales every strength the material draws: tensile by a, shear by b (a normal's spread too).
void scale_strengths(BondMaterial& material, double tensile_scale, double shear_scale);

/// The strength a test reports (UCS for the uniaxial test, BTS for the Brazilian one).
double strength_of(const std::optional<CompressionResult>& r);

}  // namespace bpm
