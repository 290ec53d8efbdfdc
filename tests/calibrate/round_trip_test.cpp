// The calibration round trip with real platens: the small cylinder example (847 particles, 3,258
// TBBM bonds, Hertz-Mindlin contacts and platens) with its known bond E_b; its stiffness by the
// explicit DEM; the calibration from an E_b three times too large must recover the known E_b: to
// 1 % after the DEM stage, to 2 % with the fast stages alone.
#include <gtest/gtest.h>

#include <cmath>

#include "calibrate/bond_parameters.hpp"
#include "calibrate/calibration.hpp"
#include "scenario/scenario.hpp"

namespace bpm {
namespace {

/// The small cylinder, its known E_b and its DEM stiffness (computed once for the tests below).
struct SmallCylinder {
  Scenario scenario = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/compression.yaml");
  double known = scenario.bond_materials[0].youngs_modulus;
  StiffnessSettings stiffness = [this] {
    StiffnessSettings s;
    s.compression = *scenario.compression;
    return s;
  }();
  double dem = estimate_sample_stiffness(scenario.model, StiffnessMethod::dem, stiffness).stiffness;

  static const SmallCylinder& get() {
    static const SmallCylinder sample;
    return sample;
  }
  /// Calibrates from 3 E_b with the given stages (empty: the defaults) to the DEM's K.
  CalibrationResult calibrate(const std::vector<StiffnessMethod>& stages, bool finish_with_dem = true) const {
    CalibrationSettings c;
    c.finish_with_dem = finish_with_dem;
    c.stiffness = stiffness;
    c.bond_damping = scenario.model.damping.bond;
    c.quantity = CalibrationQuantity::stiffness;
    c.target = dem;
    if (!stages.empty()) c.stages = stages;
    Model model = scenario.model;
    std::vector<BondMaterial> materials = scenario.bond_materials;
    set_bond_youngs_moduli(model, materials, {3.0 * known}, c.bond_damping);
    const CalibrationResult r = calibrate_bond_parameters(model, materials, c);
    for (const auto& stage : r.stages) {
      std::printf("%-14s E_b = %.6g Pa (%+.3f %% from the known), K error %+.3f %%, %d evaluations, %.2f s\n",
                  std::string(to_string(stage.method)).c_str(), stage.youngs_moduli[0],
                  100.0 * (stage.youngs_moduli[0] / known - 1.0), 100.0 * stage.error, stage.evaluations, stage.seconds);
    }
    return r;
  }
};

/// The promise: `bpmkit calibrate SCENARIO --target-K K_DEM` with no other options returns E_b
/// within 2 % of the true value. The default stages: the linear DSM with its platen walls, the
/// nonlinear DSM, then the DEM (its error at the fast answer, one corrected run).
TEST(CalibrationRoundTrip, DefaultStagesRecoverTheKnownModulusWithin2Percent) {
  const SmallCylinder& s = SmallCylinder::get();
  const CalibrationResult r = s.calibrate({});
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(r.stages[0].method, StiffnessMethod::dsm);
  EXPECT_EQ(r.stages[1].method, StiffnessMethod::dsm_nonlinear);
  EXPECT_EQ(r.stages[2].method, StiffnessMethod::dem);
  EXPECT_NEAR(r.stages[0].youngs_moduli[0], s.known, 2e-2 * s.known);  // the fast stages alone
  EXPECT_NEAR(r.stages[1].youngs_moduli[0], s.known, 2e-2 * s.known);
  EXPECT_NEAR(r.youngs_moduli[0], s.known, 1e-2 * s.known);  // after the DEM's step
  // The platen and particle contacts in series make K depend weakly on E_b on this sample too.
  EXPECT_GT(r.sensitivity, 0.3);
  EXPECT_LT(r.sensitivity, 0.7);
}

/// The stiffness tensor estimation as a first guess, the nonlinear DSM alone after it.
TEST(CalibrationRoundTrip, SteThenNonlinearDsmWithoutTheDem) {
  const SmallCylinder& s = SmallCylinder::get();
  const CalibrationResult r = s.calibrate({StiffnessMethod::ste, StiffnessMethod::dsm_nonlinear}, false);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_NEAR(r.youngs_moduli[0], s.known, 2e-2 * s.known);
}

}  // namespace
}  // namespace bpm
