// contact_law::linearise, the one source of contact stiffness for the static methods (DSM, STE,
// contact time step), against contact_law::evaluate, the DEM's law: the same elastic force, its
// derivative by central differences, and the same tangential spring.
#include <gtest/gtest.h>

#include <cmath>

#include "contacts/contact_law.hpp"

namespace bpm {
namespace {

ContactPairParameters hertz() {
  ContactPairParameters p;
  p.law = ContactLaw::hertz_mindlin;
  p.e_star = 3.5e9;
  p.g_star = 1.4e9;
  p.friction = 1e6;  // no sliding
  return p;
}

ContactPairParameters linear() {
  ContactPairParameters p;
  p.law = ContactLaw::linear;
  p.k_n = 2e5;
  p.k_t = 8e4;
  p.friction = 1e6;
  return p;
}

/// evaluate's normal force at overlap delta, at rest and without a tangential spring.
double normal_force(const ContactPairParameters& p, const contact_law::PairInertia& g,
                    double delta) {
  Vec3 spring{};
  const contact_law::Kinematics k{{0.0, 0.0, 1.0}, delta, {}, {}};
  return contact_law::evaluate(p, g, k, spring, 0.0, 0.0).normal_force;
}

TEST(ContactLawLinearised, IsTheDemLawLinearisedAtItsOverlap) {
  const contact_law::PairInertia g{5e-4, 1e-3, 1e-10};
  for (const ContactPairParameters& p : {hertz(), linear()}) {
    for (const double delta : {1e-7, 3e-6, 2e-5}) {
      const contact_law::Linearised l = contact_law::linearise(p, g, delta);
      EXPECT_EQ(l.force, normal_force(p, g, delta));
      EXPECT_DOUBLE_EQ(l.normal_secant, l.force / delta);
      const double h = 1e-4 * delta;
      const double slope =
          (normal_force(p, g, delta + h) - normal_force(p, g, delta - h)) / (2.0 * h);
      EXPECT_NEAR(l.normal_tangent, slope, 1e-7 * slope) << "delta " << delta;
      // The tangential spring: a small stretch s across the normal gives F_t = k_t s on j's side.
      Vec3 spring{2e-9, -1e-9, 0.0};
      const Vec3 stretch = spring;
      const contact_law::Kinematics k{{0.0, 0.0, 1.0}, delta, {}, {}};
      const contact_law::ContactLoad load = contact_law::evaluate(p, g, k, spring, 0.0, 0.0);
      const Vec3 tangential = load.force + load.normal_force * k.n;
      EXPECT_NEAR(norm(tangential - l.tangential * stretch), 0.0,
                  1e-12 * l.tangential * norm(stretch));
    }
  }
  // Apart: nothing.
  const contact_law::Linearised apart = contact_law::linearise(hertz(), g, -1e-6);
  EXPECT_EQ(apart.force, 0.0);
  EXPECT_EQ(apart.normal_tangent, 0.0);
  EXPECT_EQ(apart.tangential, 0.0);
}

}  // namespace
}  // namespace bpm
