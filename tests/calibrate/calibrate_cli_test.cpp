// `bpmkit calibrate` end to end: --target-E with --target-nu writes calibration.json with each
// stage's k_s / k_n and nu, and calibrated.yaml, a scenario that loads as it is (from another
// folder) with the answer's bond parameters; the refusals exit 2 with the fix and claim no folder.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "common/test_files.hpp"
#include "io/bpmkit_process.hpp"
#include "scenario/scenario.hpp"

namespace bpm {
namespace {

/// The small cylinder with parallel bonds (kappa = 5), its structure files named from a scratch
/// folder.
std::string pbm_cylinder(const test::TempDir& dir) {
  const std::string example = std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/";
  std::string text = test::read_text(example + "compression.yaml");
  auto replace = [&](const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
    }
  };
  replace("model: tbbm", "model: pbm, kappa: 5");
  replace("file: structure/", "file: " + example + "structure/");
  std::filesystem::create_directories(dir.path("input"));
  return dir.write("input/pbm.yaml", text);
}

TEST(CalibrateCli, YoungsModulusAndPoissonsRatioWriteTheCalibratedScenario) {
  const test::TempDir dir;
  const std::string scenario = pbm_cylinder(dir);
  const test::Outcome o = test::run_bpmkit(
      "calibrate " + scenario + " --target-E 1.1e8 --target-nu 0.15 --no-dem --out cal",
      dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("the body's E = 1.1e+08 Pa"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("kappa = "), std::string::npos) << o.output;
  const auto cal = nlohmann::json::parse(test::read_text(dir.path("cal/calibration.json")));
  EXPECT_EQ(cal["target_quantity"], "youngs_modulus");
  EXPECT_EQ(cal["target_poissons_ratio"], 0.15);
  EXPECT_LT(cal["poissons_ratio_range"]["min"].get<double>(), 0.15);
  EXPECT_GT(cal["poissons_ratio_range"]["max"].get<double>(), 0.15);
  const auto& last = cal["stages"].back();
  EXPECT_EQ(last["method"], "dsm-nonlinear");
  EXPECT_NEAR(last["youngs_modulus_Pa"].get<double>(), 1.1e8, 1.1e5);
  EXPECT_NEAR(last["poissons_ratio"].get<double>(), 0.15, 1e-3);
  const double e_b = last["bond_youngs_modulus_Pa"]["bond"].get<double>();
  const double ratio = last["bond_shear_to_normal_ratio"]["bond"].get<double>();

  // calibrated.yaml: the same structure, the answer's E_b and kappa = 1 / (k_s / k_n).
  const Scenario original = load_scenario(scenario);
  const Scenario calibrated = load_scenario(dir.path("cal/calibrated.yaml"));
  EXPECT_EQ(calibrated.model.particles.size(), original.model.particles.size());
  EXPECT_EQ(calibrated.model.bonds.size(), original.model.bonds.size());
  ASSERT_EQ(calibrated.bond_materials.size(), 1u);
  EXPECT_EQ(calibrated.bond_materials[0].youngs_modulus, e_b);
  EXPECT_NEAR(*calibrated.bond_materials[0].kappa, 1.0 / ratio, 1e-12 / ratio);
  EXPECT_TRUE(calibrated.compression.has_value());
}

TEST(CalibrateCli, RefusalsNameTheFixAndClaimNoFolder) {
  const test::TempDir dir;
  const std::string tbbm =
      std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/compression.yaml";
  test::Outcome o = test::run_bpmkit(
      "calibrate " + tbbm + " --target-E 1e8 --target-nu 0.2 --out a", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("use model pbm"), std::string::npos) << o.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path("a")));
  o = test::run_bpmkit("calibrate " + tbbm + " --target-E 1e8 --target-K 5e4 --out b",
                       dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("--target-platen-E"), std::string::npos) << o.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path("b")));
  // A strength test is run by `bpmkit run`; the stiffness methods measure the uniaxial test.
  const std::string tension = std::string(BPMKIT_EXAMPLES_DIR) + "/05_strength/tension.yaml";
  o = test::run_bpmkit("calibrate " + tension + " --target-E 1e8 --out c", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("compression.test"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("bpmkit run"), std::string::npos) << o.output;
}

/// The strength targets' refusals, before any DEM run or folder: a test without failure_drop, a BTS
/// without the disc's scenario, a disc that is not a Brazilian test.
TEST(CalibrateCli, StrengthTargetsRefuseWhatCannotGiveAPeak) {
  const test::TempDir dir;
  const std::string examples = std::string(BPMKIT_EXAMPLES_DIR) + "/";
  const std::string small =
      examples + "04_compression/small_cylinder/compression.yaml";  // no failure_drop
  test::Outcome o =
      test::run_bpmkit("calibrate " + small + " --target-ucs 2e6 --out a", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("compression.failure_drop"), std::string::npos) << o.output;
  const std::string ucs = examples + "05_strength/ucs.yaml";
  o = test::run_bpmkit("calibrate " + ucs + " --target-bts 3e5 --out b", dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("--disc"), std::string::npos) << o.output;
  o = test::run_bpmkit("calibrate " + ucs + " --target-bts 3e5 --disc " + ucs + " --out c",
                       dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("is not brazilian"), std::string::npos) << o.output;
  o = test::run_bpmkit("calibrate " + ucs + " --target-nu 0.2 --target-ucs 2e6 --out d",
                       dir.path(""));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("needs --target-E"), std::string::npos) << o.output;
  for (const char* folder : {"a", "b", "c", "d"})
    EXPECT_FALSE(std::filesystem::exists(dir.path(folder))) << folder;
}

}  // namespace
}  // namespace bpm
