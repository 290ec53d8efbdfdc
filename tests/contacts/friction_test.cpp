// Friction against rigid-body mechanics on an incline (gravity tilted by theta, plane z = 0):
// - rotation blocked: the sphere sticks for tan(theta) < mu (its displacement stays within the
//   tangential spring's stretch m g sin(theta) / k_t) and slides with a = g (sin - mu cos) above;
// - rotation free: a sphere rolls without slip when tan(theta) <= 7/2 mu (friction needed for
//   rolling is 2/7 m g sin(theta)), with a = 5/7 g sin(theta) and zero slip at the contact point;
//   above it slides with a = g (sin - mu cos) and spins up at 5 mu g cos(theta) / (2 R);
// - rolling friction: a sphere rolling on a level plane decelerates at 5/7 mu_r g and then stays
//   at rest (no chatter);
// - the Coulomb limit |F_t| <= mu F_n holds for any input of the kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact_helpers.hpp"
#include "contacts/contact_law.hpp"
#include "dem/simulation.hpp"

namespace bpm {
namespace {

constexpr double kG = 9.81;
constexpr double kR = 1e-3;

struct Incline {
  Model model;
  double dt = 0.0;
};

/// A sphere resting on the plane z = 0 at its static Hertz overlap, gravity tilted by theta
/// about y (down-slope is +x).
Incline incline(double theta, double mu, bool rotation_free, double mu_r = 0.0) {
  Incline s;
  Model& m = s.model;
  const ContactMaterial material = test::hertz_material(1e7, 0.3, 0.5, mu, mu_r);
  m.contacts.materials = {material};
  m.walls.push_back(test::plane({}, {0.0, 0.0, 1.0}, 0));
  m.particles.add(0, {0.0, 0.0, kR}, kR, 2500.0);
  const double mass = m.particles.mass[0];
  const double e_star = material.youngs_modulus / (2.0 * (1.0 - 0.09));
  const double delta = std::pow(mass * kG * std::cos(theta) / (4.0 / 3.0 * e_star * std::sqrt(kR)), 2.0 / 3.0);
  m.particles.position[0].z = kR - delta;
  m.gravity = {kG * std::sin(theta), 0.0, -kG * std::cos(theta)};
  if (!rotation_free) m.fix(0, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  m.finalize();
  const double k_n = 2.0 * e_star * std::sqrt(kR * delta);
  s.dt = 0.05 * std::sqrt(mass / k_n);  // 1/20 of the normal oscillation's 1/omega
  return s;
}

/// Velocity of the sphere at its contact point with the plane (slip speed along x).
double slip(const ParticleStore& p) { return p.velocity[0].x + cross(p.angular_velocity[0], {0.0, 0.0, -kR}).x; }

/// Runs to t1 and t2 and returns the mean accelerations (dv/dt, domega_y/dt) in between.
std::pair<double, double> accelerations(Incline& s, double t1, double t2, double* max_slip = nullptr) {
  Simulation sim(s.model, s.dt);
  const ParticleStore& p = s.model.particles;
  while (sim.time() < t1) sim.step();
  const double v1 = p.velocity[0].x, w1 = p.angular_velocity[0].y, time1 = sim.time();
  double worst = 0.0;
  while (sim.time() < t2) {
    sim.step();
    worst = std::max(worst, std::abs(slip(p)));
  }
  if (max_slip) *max_slip = worst;
  return {(p.velocity[0].x - v1) / (sim.time() - time1), (p.angular_velocity[0].y - w1) / (sim.time() - time1)};
}

TEST(FrictionTest, BlockedSphereSticksBelowTheFrictionAngle) {
  const double mu = 0.5, theta = std::atan(0.8 * mu);
  Incline s = incline(theta, mu, false);
  Simulation sim(s.model, s.dt);
  const ParticleStore& p = s.model.particles;
  // Largest stretch of the tangential spring: the static m g sin / k_t plus an overshoot of the
  // same size (it starts unstretched), with k_t = 8 G* sqrt(R delta).
  const double mass = p.mass[0];
  const double g_star = 1.0 / (2.0 * 2.0 * (2.0 - 0.3) * 1.3 / 1e7);
  const double delta = kR - p.position[0].z;
  const double stretch = mass * kG * std::sin(theta) / (8.0 * g_star * std::sqrt(kR * delta));
  double max_x = 0.0;
  while (sim.time() < 0.05) {
    sim.step();
    max_x = std::max(max_x, std::abs(p.position[0].x));
  }
  EXPECT_LT(max_x, 2.0 * stretch * 1.01);
  EXPECT_LT(std::abs(p.velocity[0].x), 1e-3 * kG * std::sin(theta) * 0.05);  // vs free sliding speed
}

TEST(FrictionTest, BlockedSphereSlidesWithCoulombAcceleration) {
  const double mu = 0.3, theta = std::atan(1.5 * mu);
  Incline s = incline(theta, mu, false);
  const auto [a, alpha] = accelerations(s, 0.01, 0.03);
  const double expected = kG * (std::sin(theta) - mu * std::cos(theta));
  EXPECT_NEAR(a / expected, 1.0, 1e-3);
  EXPECT_EQ(alpha, 0.0);
}

TEST(FrictionTest, FreeSphereRollsWithoutSlipBelowSevenHalvesMu) {
  const double mu = 0.3, theta = std::atan(0.8 * 3.5 * mu);
  Incline s = incline(theta, mu, true);
  double max_slip = 0.0;
  const auto [a, alpha] = accelerations(s, 0.01, 0.03, &max_slip);
  EXPECT_NEAR(a / (5.0 / 7.0 * kG * std::sin(theta)), 1.0, 1e-3);
  EXPECT_NEAR(alpha * kR / a, 1.0, 1e-3);  // rolling: a = R domega/dt
  // The contact point creeps only by the tangential spring's oscillation: << the speed reached.
  EXPECT_LT(max_slip, 1e-3 * a * 0.03);
}

TEST(FrictionTest, FreeSphereSlidesAboveSevenHalvesMu) {
  const double mu = 0.1, theta = std::atan(1.5 * 3.5 * mu);
  Incline s = incline(theta, mu, true);
  const auto [a, alpha] = accelerations(s, 0.01, 0.03);
  EXPECT_NEAR(a / (kG * (std::sin(theta) - mu * std::cos(theta))), 1.0, 1e-3);
  // Friction torque R mu m g cos over I = 2/5 m R^2.
  EXPECT_NEAR(alpha / (2.5 * mu * kG * std::cos(theta) / kR), 1.0, 1e-3);
}

TEST(FrictionTest, RollingFrictionDeceleratesAndStopsWithoutChatter) {
  const double mu = 0.5, mu_r = 0.02, v0 = 0.05;
  Incline s = incline(0.0, mu, true, mu_r);
  ParticleStore& p = s.model.particles;
  p.velocity[0].x = v0;
  p.angular_velocity[0].y = v0 / kR;  // rolling: no slip at the contact
  Simulation sim(s.model, s.dt);
  const double a = 5.0 / 7.0 * mu_r * kG;  // M = mu_r R m g against I/R + m R = 7/5 m R
  const double stop = v0 / a;
  while (sim.time() < 0.5 * stop) sim.step();
  EXPECT_NEAR(p.velocity[0].x / (v0 - a * sim.time()), 1.0, 2e-3);
  while (sim.time() < 1.2 * stop) sim.step();
  // At rest; the capped torque cannot reverse the rolling, so it stays at rest.
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    sim.step();
    worst = std::max(worst, std::abs(p.angular_velocity[0].y) * kR);
  }
  EXPECT_LT(worst, 1e-3 * v0);
  EXPECT_NEAR(p.position[0].x / (0.5 * v0 * stop), 1.0, 2e-3);  // distance v0^2 / (2a)
}

TEST(FrictionTest, TangentialForceNeverExceedsCoulomb) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const ContactLaw law : {ContactLaw::hertz_mindlin, ContactLaw::linear}) {
    ContactMaterial m = law == ContactLaw::hertz_mindlin ? test::hertz_material(1e8, 0.3, 0.5, 0.4)
                                                         : test::linear_material(1e4, 8e3, 0.5, 0.4);
    ContactModel cm;
    cm.materials = {m};
    const ContactTable table(cm);
    const ContactPairParameters& c = table(0, 0);
    Vec3 spring;
    int sliding = 0;
    for (int k = 0; k < 20000; ++k) {
      Vec3 n{u(rng), u(rng), u(rng)};
      if (k % 2 == 0) n = Vec3{0.1 * u(rng), 0.1 * u(rng), 1.0};  // mostly a steady normal
      n = n / norm(n);
      const contact_law::Kinematics kin{n, 1e-5 * (1.0 + u(rng)), {u(rng), u(rng), u(rng)}, {}};
      const contact_law::ContactLoad load = contact_law::evaluate(c, {5e-4, 1e-5, 1e-12}, kin, spring, 1e-5, 1e-5);
      const double f_n = -dot(load.force, n);
      const Vec3 f_t = load.force + f_n * n;
      // Round-off of splitting the force into normal and tangential parts: 1e-12 of its size.
      ASSERT_LE(norm(f_t), c.friction * std::max(0.0, f_n) + 1e-12 * norm(load.force)) << "step " << k;
      ASSERT_NEAR(f_n, load.normal_force, 1e-12 * std::abs(f_n));
      if (norm(f_t) >= c.friction * f_n * (1.0 - 1e-12)) ++sliding;
    }
    EXPECT_GT(sliding, 100);  // the cap was actually exercised
  }
}

}  // namespace
}  // namespace bpm

namespace bpm {
namespace {

/// The static methods' tangential force (contact_law::coulomb_capped): the spring below the
/// Coulomb limit, the limit along the spring above it, nothing without a pressing normal force.
TEST(StaticFriction, SpringBelowTheLimitCoulombForceAbove) {
  ContactPairParameters p;
  p.friction = 0.5;
  const Vec3 s{1e-6, -2e-6, 0.0};
  const double k_t = 1e5;  // |k_t s| = 0.2236 N
  const Vec3 below = contact_law::coulomb_capped(p, k_t, 1.0, s);  // limit 0.5 N
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(below[k], k_t * s[k]);
  const Vec3 above = contact_law::coulomb_capped(p, k_t, 0.2, s);  // limit 0.1 N
  EXPECT_NEAR(norm(above), 0.1, 1e-15);
  EXPECT_NEAR(dot(above, s) / (norm(above) * norm(s)), 1.0, 1e-15);
  EXPECT_EQ(norm(contact_law::coulomb_capped(p, k_t, -1.0, s)), 0.0);  // pulling: no friction
  p.friction = 0.0;
  EXPECT_EQ(norm(contact_law::coulomb_capped(p, k_t, 1.0, s)), 0.0);  // frictionless
}

}  // namespace
}  // namespace bpm
