// The bond-model registry (Chen 2022, Tables 1, 6 and 9, Eq. 8, 17-26, 45): every registered model's
// stiffness set and contact-point offset against closed forms written out here independently of
// src/bonds/bond_model.cpp, and Chen Table 5 (case 3) reproduced to the digits the paper prints.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>

#include "bonds/bond_model.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

constexpr double kPi = std::numbers::pi;

BondMaterial material(const std::string& key, double E = 70e9, double nu = 0.22) {
  BondMaterial m;
  m.name = key;
  m.model = key;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  return m;
}

/// A stocky, unequal-radius bond so that every term (Phi, the offset) is far from trivial.
BondGeometry geometry() { return {0.7e-3, 2.9e-3, 1.9e-3, 1.1e-3}; }

void expect_rel(double actual, double expected, double rel, const std::string& what) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << what;
}

void expect_stiffness(const BondStiffness& k, const BondStiffness& expected, const std::string& what) {
  constexpr double rel = 1e-14;
  expect_rel(k.k_n, expected.k_n, rel, what + " k_n");
  expect_rel(k.k_s, expected.k_s, rel, what + " k_s");
  expect_rel(k.k_tor, expected.k_tor, rel, what + " k_tor");
  expect_rel(k.k_ben, expected.k_ben, rel, what + " k_ben");
}

// Closed forms, written from the paper (not from bond_model.cpp).
double k_normal(const BondMaterial& m, const BondGeometry& g) {  // Table 1/6/9: E pi r^2 / L
  return m.youngs_modulus * kPi * g.radius * g.radius / g.length;
}
double k_euler(const BondMaterial& m, const BondGeometry& g) {  // Eq. 26: 12 E I / L^3, I = pi r^4/4
  const double I = 0.25 * kPi * std::pow(g.radius, 4);
  return 12.0 * m.youngs_modulus * I / std::pow(g.length, 3);
}
double phi_s(const BondMaterial& m, const BondGeometry& g) {  // Eq. 25
  return 20.0 * g.radius * g.radius * (1.0 + m.poisson_ratio) / (3.0 * g.length * g.length);
}
double k_timoshenko(const BondMaterial& m, const BondGeometry& g) {  // Eq. 18
  return k_euler(m, g) / (1.0 + phi_s(m, g));
}
/// Beam bonds (Table 6/9): k_tor = 0.25 k_n r^2 / (1 + nu) (= G J / L), k_ben = 0.25 k_n r^2 (= E I / L).
BondStiffness beam(const BondMaterial& m, const BondGeometry& g, double k_s) {
  const double kn = k_normal(m, g), r2 = g.radius * g.radius;
  return {kn, k_s, 0.25 * kn * r2 / (1.0 + m.poisson_ratio), 0.25 * kn * r2};
}
/// Parallel bond (Table 1): k_s = k_n / kappa, k_tor = 0.5 k_s r^2, k_ben = 0.25 k_n r^2.
BondStiffness parallel(const BondMaterial& m, const BondGeometry& g, double k_s) {
  const double kn = k_normal(m, g), r2 = g.radius * g.radius;
  return {kn, k_s, 0.5 * k_s * r2, 0.25 * kn * r2};
}

struct Expected {
  std::function<BondStiffness(const BondMaterial&, const BondGeometry&)> stiffness;
  bool gap_centre;  ///< contact point at the gap centre (Eq. 1-2) rather than the beam centre (Eq. 44)
};

/// One closed form per registered key. A model added to the registry without an entry here fails
/// RegistryTest.EveryModelHasClosedForm (bond_model.hpp asks for a test with every new model).
const std::map<std::string, Expected>& closed_forms() {
  static const std::map<std::string, Expected> forms{
      {"pbm",
       {[](const BondMaterial& m, const BondGeometry& g) {
          return parallel(m, g, k_normal(m, g) / (2.0 * (1.0 + m.poisson_ratio)));  // Eq. 8 default
        },
        true}},
      {"brendel",
       {[](const BondMaterial& m, const BondGeometry& g) {
          return parallel(m, g, k_normal(m, g) / (2.0 * (1.0 + m.poisson_ratio)));
        },
        true}},
      {"ebbm", {[](const BondMaterial& m, const BondGeometry& g) { return beam(m, g, k_euler(m, g)); }, false}},
      {"tbbm",
       {[](const BondMaterial& m, const BondGeometry& g) { return beam(m, g, k_timoshenko(m, g)); }, false}},
      {"obermayr",
       {[](const BondMaterial& m, const BondGeometry& g) {  // Eq. 45 with alpha_s = 1 by default
          return beam(m, g, k_normal(m, g) / (2.0 * (1.0 + m.poisson_ratio)));
        },
        false}},
  };
  return forms;
}

TEST(RegistryTest, EveryModelHasClosedForm) {
  ASSERT_GE(bond_models().size(), 5u);
  for (const BondModelInfo& info : bond_models()) {
    const std::string key(info.key);
    const auto it = closed_forms().find(key);
    if (it == closed_forms().end()) {
      ADD_FAILURE() << "registered bond model '" << key << "' has no closed-form test in tests/bonds";
      continue;
    }
    const BondMaterial m = material(key);
    const BondGeometry g = geometry();
    const BondConstants c = make_bond_constants(m, g);
    expect_stiffness(c.stiffness, it->second.stiffness(m, g), key);
    // Contact point: gap centre a_alpha = R_a + g_c/2 = L/2 + (R_a - R_b)/2 (Eq. 1-2); beam centre 0.
    const double offset = it->second.gap_centre ? 0.5 * (g.radius_alpha - g.radius_beta) : 0.0;
    EXPECT_NEAR(c.arm_offset, offset, 1e-18) << key;
    EXPECT_EQ(info.contact_point == ContactPointRule::gap_centre, it->second.gap_centre) << key;
  }
  for (const auto& [key, form] : closed_forms()) EXPECT_NO_THROW(find_bond_model(key)) << key;
}

TEST(RegistryTest, StiffnessValuesAgainstHandNumbers) {
  // One fully hand-evaluated case guards the closed forms above as well: E = 200 GPa, nu = 0.3,
  // r_b = 0.2 m, L_b = 0.4 m (Chen case 1): A = 0.1256637 m^2, I = 1.256637e-3 m^4, Phi = 2.1667.
  const BondMaterial m = material("tbbm", 200e9, 0.3);
  const BondGeometry g{0.2, 0.4, 0.2, 0.2};
  const BondStiffness k = make_bond_constants(m, g).stiffness;
  expect_rel(k.k_n, 6.283185307e10, 1e-9, "k_n = E A / L");
  expect_rel(k.k_s, 4.71238898e10 / (1.0 + 13.0 / 6.0), 1e-9, "k_s = 12 E I / (L^3 (1 + Phi))");
  expect_rel(k.k_tor, 6.283185307e8 / 1.3, 1e-9, "k_tor = E I / (L (1 + nu))");
  expect_rel(k.k_ben, 6.283185307e8, 1e-9, "k_ben = E I / L");
  EXPECT_NEAR(timoshenko_phi(0.2, 0.4, 0.3), 13.0 / 6.0, 1e-15);
}

TEST(RegistryTest, PbmUserKappa) {
  BondMaterial m = material("pbm");
  const BondGeometry g = geometry();
  m.kappa = 3.7;
  const BondConstants c = make_bond_constants(m, g);
  expect_stiffness(c.stiffness, parallel(m, g, k_normal(m, g) / 3.7), "pbm kappa=3.7");
  // Brendel fixes kappa = 2(1+nu) (Eq. 8) whatever the material says.
  m.model = "brendel";
  expect_stiffness(make_bond_constants(m, g).stiffness,
                   parallel(m, g, k_normal(m, g) / (2.0 * (1.0 + m.poisson_ratio))), "brendel ignores kappa");
}

TEST(RegistryTest, ObermayrShearCoefficient) {
  BondMaterial m = material("obermayr");
  const BondGeometry g = geometry();
  m.shear_coefficient = 0.85;
  expect_stiffness(make_bond_constants(m, g).stiffness,
                   beam(m, g, 0.85 * k_normal(m, g) / (2.0 * (1.0 + m.poisson_ratio))), "obermayr alpha_s");
}

TEST(RegistryTest, ShearOverride) {
  const BondGeometry g = geometry();
  for (const std::string key : {"pbm", "ebbm", "tbbm", "obermayr"}) {
    BondMaterial m = material(key);
    const bool spring = key == "pbm";
    auto expected = [&](double k_s) { return spring ? parallel(m, g, k_s) : beam(m, g, k_s); };
    m.shear_override = ShearOverride::value;
    m.shear_stiffness = 1.234e6;
    expect_stiffness(make_bond_constants(m, g).stiffness, expected(1.234e6), key + " override value");
    m.shear_override = ShearOverride::euler_bernoulli;
    expect_stiffness(make_bond_constants(m, g).stiffness, expected(k_euler(m, g)), key + " override EB");
    m.shear_override = ShearOverride::timoshenko;
    expect_stiffness(make_bond_constants(m, g).stiffness, expected(k_timoshenko(m, g)), key + " override T");
  }
}

TEST(RegistryTest, ContactOffsetFollowsRadii) {
  // Gap centre moves towards the smaller particle (Chen section 4.3); beam centre never moves.
  const BondGeometry g{0.2, 1.0, 0.2, 0.6};
  EXPECT_DOUBLE_EQ(make_bond_constants(material("pbm"), g).arm_offset, -0.2);
  EXPECT_DOUBLE_EQ(make_bond_constants(material("brendel"), g).arm_offset, -0.2);
  EXPECT_EQ(make_bond_constants(material("tbbm"), g).arm_offset, 0.0);
  EXPECT_EQ(make_bond_constants(material("ebbm"), g).arm_offset, 0.0);
  EXPECT_EQ(make_bond_constants(material("obermayr"), g).arm_offset, 0.0);
}

TEST(RegistryTest, UnknownKeyThrowsListingKeys) {
  EXPECT_THROW(find_bond_model("timoshenko"), InputError);
  EXPECT_THROW(make_bond_constants(material("hertz"), geometry()), InputError);
  try {
    find_bond_model("hertz", "bond_materials[2].model");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bond_materials[2].model"), std::string::npos) << what;
    EXPECT_NE(what.find("'hertz'"), std::string::npos) << what;
    for (const BondModelInfo& info : bond_models()) {
      EXPECT_NE(what.find(std::string(info.key)), std::string::npos) << what << " lacks " << info.key;
    }
  }
}

// Chen Table 5 (case 3): E = 200 GPa, nu = 0.3, r_b = 0.2 m, n bonds over 4 m (L_b = 4/n), in GN/m
// (the paper's "GPa m"). The paper truncates rather than rounds some entries (2.416 for 2.4166,
// 12.56 for 12.566, 9.66 for 9.666), so the comparison is to 1e-3 relative: four printed digits.
struct Table5Row {
  int bonds;
  double k_n, pbm, ebbm, tbbm;
};
constexpr Table5Row kTable5[] = {
    {1, 6.283, 2.416, 0.04712, 0.04612},  {2, 12.56, 4.833, 0.3769, 0.3469},
    {4, 25.13, 9.66, 3.016, 2.240},       {6, 37.69, 14.50, 10.18, 5.718},
    {8, 50.26, 19.33, 24.13, 10.11},      {10, 62.83, 24.17, 47.12, 14.88},
};

TEST(Table5Test, Case3StiffnessesReproduced) {
  for (const Table5Row& row : kTable5) {
    const BondGeometry g{0.2, 4.0 / row.bonds, 0.2, 0.2};
    auto k = [&](const char* key) { return make_bond_constants(material(key, 200e9, 0.3), g).stiffness; };
    const std::string at = "bonds=" + std::to_string(row.bonds);
    expect_rel(k("tbbm").k_n * 1e-9, row.k_n, 1e-3, at + " k_n");
    expect_rel(k("ebbm").k_n * 1e-9, row.k_n, 1e-3, at + " k_n ebbm");
    expect_rel(k("pbm").k_n * 1e-9, row.k_n, 1e-3, at + " k_n pbm");
    expect_rel(k("pbm").k_s * 1e-9, row.pbm, 1e-3, at + " k_s pbm");
    expect_rel(k("ebbm").k_s * 1e-9, row.ebbm, 1e-3, at + " k_s ebbm");
    expect_rel(k("tbbm").k_s * 1e-9, row.tbbm, 1e-3, at + " k_s tbbm");
  }
}

TEST(Table5Test, ShearRatiosQuotedInSection41) {
  // "When the number of bonds increases to 10, the shear stiffness of the parallel bond is 1.6 times
  // larger than that of TBBM. The shear stiffness of the EBBM is 3.1 times larger."
  const BondGeometry g{0.2, 0.4, 0.2, 0.2};
  auto k_s = [&](const char* key) { return make_bond_constants(material(key, 200e9, 0.3), g).stiffness.k_s; };
  // The paper truncates: the ratios are 1.624 and 3.167.
  EXPECT_NEAR(k_s("pbm") / k_s("tbbm"), 1.624, 1e-3);
  EXPECT_NEAR(k_s("ebbm") / k_s("tbbm"), 3.167, 1e-3);
  // With kappa = 2(1+nu) the parallel bond's twisting stiffness equals the beams' (section 3).
  const BondStiffness pbm = make_bond_constants(material("pbm", 200e9, 0.3), g).stiffness;
  const BondStiffness tbbm = make_bond_constants(material("tbbm", 200e9, 0.3), g).stiffness;
  EXPECT_NEAR(pbm.k_tor, tbbm.k_tor, 1e-12 * tbbm.k_tor);
  EXPECT_NEAR(pbm.k_ben, tbbm.k_ben, 1e-12 * tbbm.k_ben);
}

}  // namespace
}  // namespace bpm
