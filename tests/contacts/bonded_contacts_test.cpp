// Bonded pairs (Jarolin section 2: a bond superimposes on or replaces the particle contact; Chen
// section 2.1: PBM's non-bonded component acts only while the particles physically touch):
// - superimpose: an overlapping bonded pair carries the Hertz force besides the bond, a bonded
//   pair with a gap carries none;
// - replace: no contact force while the bond is intact, the Hertz force once it has broken;
// - a per-pair rule overrides the model's default.
#include <gtest/gtest.h>

#include <cmath>

#include "../dem/dem_helpers.hpp"
#include "contact_helpers.hpp"
#include "contacts/contact_forces.hpp"

namespace bpm {
namespace {

constexpr double kR = 1e-3;

/// Two spheres at centre distance 2R - overlap (negative: a gap), bonded, finalised.
Model bonded_pair(double overlap, std::int32_t material_b = 0) {
  Model model;
  model.particles.add(0, {0.0, 0.0, 0.0}, kR, 2500.0, 0);
  model.particles.add(1, {2.0 * kR - overlap, 0.0, 0.0}, kR, 2500.0, material_b);
  test::bond(model, 0, 1, test::steel_bond("tbbm"));
  model.finalize();
  return model;
}

double contact_force(const Model& model, const ContactModel& cm) {
  const ContactTable table(cm);
  ContactForces contacts(table, model.particles, 1e-4);
  contacts.update_list(model.particles, model.bonds);
  contacts.compute(model.particles, model.bonds, 0.0, 1e-7);
  return contacts.list().size() == 1 ? contacts.normal_force()[0] : 0.0;
}

ContactModel contact_model(BondedContacts mode) {
  ContactModel cm;
  cm.particle_particle = true;
  cm.materials = {test::hertz_material(1e8, 0.3, 0.5, 0.3), test::hertz_material(1e8, 0.3, 0.5, 0.3)};
  cm.bonded = mode;
  return cm;
}

double hertz(double overlap) {
  const double e_star = 1e8 / (2.0 * (1.0 - 0.09));
  return 4.0 / 3.0 * e_star * std::sqrt(0.5 * kR) * std::pow(overlap, 1.5);
}

TEST(BondedContactsTest, SuperimposedContactActsOnlyOnPhysicalContact) {
  const ContactModel cm = contact_model(BondedContacts::superimpose);
  EXPECT_NEAR(contact_force(bonded_pair(1e-5), cm) / hertz(1e-5), 1.0, 1e-12);
  EXPECT_EQ(contact_force(bonded_pair(-1e-5), cm), 0.0);  // a gap: the bond alone
}

TEST(BondedContactsTest, ReplacedContactActsOnceTheBondHasBroken) {
  const ContactModel cm = contact_model(BondedContacts::replace);
  Model model = bonded_pair(1e-5);
  ASSERT_EQ(model.bonds.intact.size(), 1u);
  EXPECT_EQ(contact_force(model, cm), 0.0);
  model.bonds.intact[0] = 0;
  EXPECT_NEAR(contact_force(model, cm) / hertz(1e-5), 1.0, 1e-12);
}

TEST(BondedContactsTest, PairRuleOverridesTheModelDefault) {
  ContactModel cm = contact_model(BondedContacts::superimpose);
  ContactPairRule rule;
  rule.a = 1;
  rule.b = 0;
  rule.bonded = BondedContacts::replace;
  cm.pair_rules.push_back(rule);
  EXPECT_EQ(contact_force(bonded_pair(1e-5, 1), cm), 0.0);               // materials (0, 1): replace
  EXPECT_NEAR(contact_force(bonded_pair(1e-5, 0), cm) / hertz(1e-5), 1.0, 1e-12);  // (0, 0): default
}

}  // namespace
}  // namespace bpm
