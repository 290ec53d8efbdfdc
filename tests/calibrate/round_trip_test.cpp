// The calibration round trip with real platens: the small cylinder example (847 particles, 3,258
// TBBM bonds, Hertz-Mindlin contacts and platens) with its known bond E_b; its stiffness by the
// explicit DEM; the calibration from an E_b three times too large must recover the known E_b: to
// 1 % after the DEM stage, to 2 % with the fast stages alone.
#include <gtest/gtest.h>

#include <cmath>

#include "calibrate/bond_parameters.hpp"
#include "calibrate/calibration.hpp"
#include "common/test_files.hpp"
#include "core/error.hpp"
#include "scenario/scenario.hpp"

namespace bpm {
namespace {

/// The stiffness methods' settings: the scenario's compression test.
StiffnessSettings settings_of(const Scenario& scenario) {
  StiffnessSettings s;
  s.compression = *scenario.compression;
  return s;
}

/// The small cylinder, its known E_b and its DEM stiffness (computed once for the tests below).
struct SmallCylinder {
  Scenario scenario = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) +
                                    "/04_compression/small_cylinder/compression.yaml");
  double known = scenario.bond_materials[0].youngs_modulus;
  StiffnessSettings stiffness = settings_of(scenario);
  StiffnessEstimate dem_estimate =
      estimate_sample_stiffness(scenario.model, StiffnessMethod::dem, stiffness);
  double dem = dem_estimate.stiffness;

  static const SmallCylinder& get() {
    static const SmallCylinder sample;
    return sample;
  }
  /// Calibrates from 3 E_b with the given stages (empty: the defaults) to the DEM's K.
  CalibrationResult calibrate(const std::vector<StiffnessMethod>& stages,
                              bool finish_with_dem = true) const {
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
      std::printf(
          "%-14s E_b = %.6g Pa (%+.3f %% from the known), K error %+.3f %%, %d evaluations, %.2f "
          "s\n",
          std::string(to_string(stage.method)).c_str(), stage.youngs_moduli[0],
          100.0 * (stage.youngs_moduli[0] / known - 1.0), 100.0 * stage.error, stage.evaluations,
          stage.seconds);
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
  const CalibrationResult r =
      s.calibrate({StiffnessMethod::ste, StiffnessMethod::dsm_nonlinear}, false);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_NEAR(r.youngs_moduli[0], s.known, 2e-2 * s.known);
}

/// `calibrate --target-E` aims at the body's E (strain gauges on the middle third), not K l / A:
/// with the DEM's body E as the target, the fast stages alone recover the known E_b within 2 %.
TEST(CalibrationRoundTrip, TheBodysYoungsModulusFromTheFastStages) {
  const SmallCylinder& s = SmallCylinder::get();
  ASSERT_TRUE(s.dem_estimate.body.valid);
  CalibrationSettings c;
  c.finish_with_dem = false;
  c.stiffness = s.stiffness;
  c.bond_damping = s.scenario.model.damping.bond;
  c.target = s.dem_estimate.body.youngs_modulus;  // quantity: the body's E, the default
  Model model = s.scenario.model;
  std::vector<BondMaterial> materials = s.scenario.bond_materials;
  set_bond_youngs_moduli(model, materials, {3.0 * s.known}, c.bond_damping);
  const CalibrationResult r = calibrate_bond_parameters(model, materials, c);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_NEAR(r.youngs_moduli[0], s.known, 2e-2 * s.known);
  EXPECT_LE(std::abs(r.stages.back().error), c.tolerance);
  // The body's E is 2-3 times K l / A here (the platen contacts' compliance is not in it), and
  // nearly proportional to E_b: the contacts are in parallel with the bonds, not in series.
  EXPECT_GT(r.stages.back().measured.youngs_modulus, 2.0 * s.dem_estimate.youngs_modulus);
  EXPECT_GT(r.sensitivity, 0.8);
}

/// The small cylinder with parallel bonds (kappa = 2.5) and its DEM's body E and nu: the truth of
/// the E-and-nu calibration.
struct PbmCylinder {
  static constexpr double kKappa = 2.5;
  Scenario scenario = [] {
    const std::string path =
        std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/compression.yaml";
    std::string text = test::read_text(path);
    const std::string tbbm = "model: tbbm";
    text.replace(text.find(tbbm), tbbm.size(), "model: pbm, kappa: 2.5");
    return load_scenario_text(text, path);
  }();
  double known = scenario.bond_materials[0].youngs_modulus;
  StiffnessSettings stiffness = settings_of(scenario);
  StiffnessEstimate dem =
      estimate_sample_stiffness(scenario.model, StiffnessMethod::dem, stiffness);

  static const PbmCylinder& get() {
    static const PbmCylinder sample;
    return sample;
  }
  CalibrationSettings settings(double nu) const {
    CalibrationSettings c;
    c.stiffness = stiffness;
    c.bond_damping = scenario.model.damping.bond;
    c.target = dem.body.youngs_modulus;
    c.target_poissons_ratio = nu;
    return c;
  }
};

/// The promise of `calibrate --target-E E --target-nu NU`: from E_b x 3 and kappa = 10, the DEM's
/// body E and nu come back within 1 % and 0.01 after the DEM stage, and the fast stages alone find
/// the known E_b within 2 % and kappa within 5 %.
TEST(CalibrationRoundTrip, YoungsModulusAndPoissonsRatioTogether) {
  const PbmCylinder& s = PbmCylinder::get();
  ASSERT_TRUE(s.dem.body.valid);
  const CalibrationSettings c = s.settings(s.dem.body.poissons_ratio);
  Model model = s.scenario.model;
  std::vector<BondMaterial> materials = s.scenario.bond_materials;
  materials[0].kappa = 10.0;
  set_bond_youngs_moduli(model, materials, {3.0 * s.known}, c.bond_damping);
  const CalibrationResult r = calibrate_bond_parameters(model, materials, c);
  ASSERT_EQ(r.stages.size(), 3u);
  ASSERT_TRUE(r.poissons_ratio_range);
  EXPECT_LT(r.poissons_ratio_range->low, s.dem.body.poissons_ratio);
  EXPECT_GT(r.poissons_ratio_range->high, s.dem.body.poissons_ratio);
  for (const CalibrationStage& st : r.stages) {
    std::printf(
        "%-14s E_b = %.6g Pa (%+.3f %%), kappa = %.5g (%+.3f %%), E error %+.3f %%, nu error "
        "%+.4f, %d evaluations\n",
        std::string(to_string(st.method)).c_str(), st.youngs_moduli[0],
        100.0 * (st.youngs_moduli[0] / s.known - 1.0), 1.0 / st.shear_to_normal_ratios[0],
        100.0 * (1.0 / st.shear_to_normal_ratios[0] / PbmCylinder::kKappa - 1.0), 100.0 * st.error,
        st.poissons_ratio_error, st.evaluations);
  }
  const CalibrationStage& fast = r.stages[1];
  EXPECT_EQ(fast.method, StiffnessMethod::dsm_nonlinear);
  EXPECT_NEAR(fast.youngs_moduli[0], s.known, 2e-2 * s.known);
  EXPECT_NEAR(1.0 / fast.shear_to_normal_ratios[0], PbmCylinder::kKappa,
              5e-2 * PbmCylinder::kKappa);
  const CalibrationStage& dem = r.stages[2];
  EXPECT_EQ(dem.method, StiffnessMethod::dem);
  EXPECT_LE(std::abs(dem.error), 1e-2);  // the DEM's own E and nu at the answer
  EXPECT_LE(std::abs(dem.poissons_ratio_error), 1e-2);
  EXPECT_NEAR(r.youngs_moduli[0], s.known, 1e-2 * s.known);
  ASSERT_TRUE(r.jacobian);
  EXPECT_LT((*r.jacobian)[3], 0.0);  // a stiffer shear lowers nu
}

/// A nu the packing cannot reach by k_s / k_n: refused with the range, before any search.
TEST(CalibrationRoundTrip, UnreachablePoissonsRatioGivesTheRange) {
  const PbmCylinder& s = PbmCylinder::get();
  for (const double nu : {0.45, -0.8}) {
    try {
      calibrate_bond_parameters(s.scenario.model, s.scenario.bond_materials, s.settings(nu));
      FAIL() << "no error for nu = " << nu;
    } catch (const InputError& e) {
      const std::string text = e.what();
      EXPECT_NE(text.find("out of the range this packing reaches"), std::string::npos) << text;
      EXPECT_NE(text.find("k_s / k_n = 10 to"), std::string::npos) << text;
    }
  }
}

}  // namespace
}  // namespace bpm
