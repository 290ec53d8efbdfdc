// The calibration round trip of the issue with real platens: the small cylinder example
// (847 particles, 3,258 TBBM bonds, Hertz-Mindlin contacts and platens) with its known bond E_b;
// its stiffness by the explicit DEM; the calibration (STE, nonlinear DSM, DEM) from an E_b three
// times too large must recover the known E_b to 1 %.
#include <gtest/gtest.h>

#include <cmath>

#include "calibrate/bond_youngs_modulus.hpp"
#include "calibrate/calibration.hpp"
#include "io/scenario.hpp"

namespace bpm {
namespace {

TEST(CalibrationRoundTrip, SmallCylinderWithPlatens) {
  Scenario scenario = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/compression.yaml");
  const double known = scenario.bond_materials[0].youngs_modulus;
  CalibrationSettings c;
  c.stiffness.compression = *scenario.compression;
  c.bond_damping = scenario.model.damping.bond;
  c.target_stiffness = estimate_sample_stiffness(scenario.model, StiffnessMethod::dem, c.stiffness).stiffness;
  c.stages = {StiffnessMethod::ste, StiffnessMethod::dsm_nonlinear, StiffnessMethod::dem};

  std::vector<BondMaterial> materials = scenario.bond_materials;
  set_bond_youngs_moduli(scenario.model, materials, {3.0 * known}, c.bond_damping);
  const CalibrationResult r = calibrate_bond_youngs_modulus(scenario.model, materials, c);
  for (const auto& stage : r.stages) {
    std::printf("%-14s E_b = %.6g Pa (%+.3f %% from the known), K error %+.3f %%, %d evaluations, %.2f s\n",
                std::string(to_string(stage.method)).c_str(), stage.youngs_moduli[0],
                100.0 * (stage.youngs_moduli[0] / known - 1.0), 100.0 * stage.error, stage.evaluations, stage.seconds);
  }
  EXPECT_NEAR(r.youngs_moduli[0], known, 1e-2 * known);
  EXPECT_NEAR(r.stages[1].youngs_moduli[0], known, 3e-2 * known);  // the nonlinear DSM alone
}

}  // namespace
}  // namespace bpm
