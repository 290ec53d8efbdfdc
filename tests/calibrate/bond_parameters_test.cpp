// The calibration's parameters (calibrate/bond_parameters.hpp): k_s / k_n set through each model's
// own parameter and re-derived into every bond (Chen Table 1, Eq. 45), and the models without a
// free ratio refused by name.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "calibrate/bond_parameters.hpp"
#include "calibrate/calibration.hpp"
#include "core/error.hpp"
#include "dsm/dsm_helpers.hpp"

namespace bpm {
namespace {

struct Sample {
  Model model = test::flat_ended_lattice(3, 3, 4, 1e-3, 0.2, 7);
  std::vector<BondMaterial> materials{test::steel_bond("tbbm")};
  explicit Sample(const std::string& model_key) {
    materials[0].model = model_key;
    rederive_bond_stiffness(model, materials, 0.0);
  }
};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(BondParameters, ParallelBondRatioIsOneOverKappa) {
  Sample s("pbm");
  BondMaterial& m = s.materials[0];
  EXPECT_DOUBLE_EQ(shear_to_normal_ratio(m),
                   1.0 / (2.0 * 1.3));  // kappa = 2 (1 + nu_b), Chen Eq. 8
  set_shear_to_normal_ratio(m, 0.2);
  EXPECT_DOUBLE_EQ(*m.kappa, 5.0);
  EXPECT_EQ(shear_ratio_parameter(m), "kappa");
  const std::vector<BondStiffness> before = s.model.bonds.stiffness;
  rederive_bond_stiffness(s.model, s.materials, 0.0);
  for (std::size_t i = 0; i < before.size(); ++i) {
    const BondStiffness& k = s.model.bonds.stiffness[i];
    const double r2 = s.model.bonds.radius[i] * s.model.bonds.radius[i];
    EXPECT_DOUBLE_EQ(k.k_n, before[i].k_n);  // k_n and k_ben do not move
    EXPECT_DOUBLE_EQ(k.k_ben, before[i].k_ben);
    EXPECT_NEAR(k.k_s, 0.2 * k.k_n, 1e-12 * k.k_n);
    EXPECT_NEAR(k.k_tor, 0.5 * k.k_s * r2, 1e-12 * k.k_tor);  // Chen Table 1
  }
}

TEST(BondParameters, ObermayrRatioIsTheShearCoefficientOverTwoOnePlusNu) {
  Sample s("obermayr");
  BondMaterial& m = s.materials[0];
  EXPECT_DOUBLE_EQ(shear_to_normal_ratio(m), 1.0 / 2.6);  // alpha_s = 1 (Chen Eq. 45)
  set_shear_to_normal_ratio(m, 0.52);
  EXPECT_NEAR(*m.shear_coefficient, 0.52 * 2.6, 1e-15);
  EXPECT_EQ(shear_ratio_parameter(m), "shear_coefficient");
  rederive_bond_stiffness(s.model, s.materials, 0.0);
  for (const BondStiffness& k : s.model.bonds.stiffness)
    EXPECT_NEAR(k.k_s, 0.52 * k.k_n, 1e-12 * k.k_n);
}

TEST(BondParameters, ModelsWithoutAFreeRatioAreRefusedByName) {
  for (const char* key : {"tbbm", "ebbm", "brendel"}) {
    const Sample s(key);
    const std::string message = error_of([&] { shear_to_normal_ratio(s.materials[0]); });
    EXPECT_NE(message.find(std::string("model ") + key), std::string::npos) << message;
    EXPECT_NE(message.find("use model pbm"), std::string::npos) << message;
  }
  Sample s("pbm");
  s.materials[0].shear_override = ShearOverride::value;
  s.materials[0].shear_stiffness = 1e6;
  EXPECT_NE(error_of([&] { shear_to_normal_ratio(s.materials[0]); }).find("shear_stiffness"),
            std::string::npos);
}

/// `calibrate --target-nu` on a Timoshenko sample: refused before any evaluation, naming the model.
TEST(BondParameters, CalibrationOfNuRefusesATimoshenkoBond) {
  const Sample s("tbbm");
  CalibrationSettings c;
  c.stiffness.compression = test::compression_along_z(1e-5);
  c.target = 1e9;
  c.target_poissons_ratio = 0.2;
  EXPECT_NE(
      error_of([&] { calibrate_bond_parameters(s.model, s.materials, c); }).find("model tbbm"),
      std::string::npos);
  c.target_poissons_ratio = 0.7;  // no material has it
  EXPECT_NE(error_of([&] { calibrate_bond_parameters(s.model, s.materials, c); }).find("(-1, 0.5)"),
            std::string::npos);
}

}  // namespace
}  // namespace bpm
