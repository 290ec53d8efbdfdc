// Uniaxial compression of a bonded column between a fixed floor and a moving lid (Jarolin section
// 3.2.3: the wall contacts, the bonds and, where they superimpose, the particle contacts act as
// springs in series). Five spheres bonded in a line along z, lateral DOFs fixed, the lid moving
// down slowly with particle damping on (quasi-static). For a lid travel d the force F solves
//   d = 2 delta_w(F) + 4 x(F),  delta_w: Hertz overlap at each wall,
//   x(F): the shortening of one link, F = k_n x (replace) or F = k_n x + Hertz_pp(x) (superimpose).
// The lid force must match that F within 1 % (quasi-static lag and O(dt^2)).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "../contacts/contact_helpers.hpp"
#include "../dem/dem_helpers.hpp"
#include "dem/simulation.hpp"

namespace bpm {
namespace {

constexpr double kR = 1e-3;
constexpr double kE = 1e8, kNu = 0.3;

/// Root of the increasing function f on [lo, hi] by bisection.
double solve(const std::function<double(double)>& f, double lo, double hi) {
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Column {
  Model model;
  double k_n = 0.0;
};

Column column(BondedContacts mode) {
  Column c;
  Model& m = c.model;
  for (int i = 0; i < 5; ++i) {
    m.particles.add(i, {0.0, 0.0, kR + 2.0 * kR * i}, kR, 2500.0);
    m.fix(i, {1.0, 1.0, 0.0}, {1.0, 1.0, 1.0});
  }
  BondMaterial bond = test::steel_bond("tbbm");
  bond.youngs_modulus = 1e6;  // k_n = E A / L = 1e3 N/m, comparable to the contacts
  for (int i = 0; i + 1 < 5; ++i) test::bond(m, i, i + 1, bond);
  m.contacts.particle_particle = true;
  m.contacts.bonded = mode;
  m.contacts.materials = {test::hertz_material(kE, kNu, 0.5)};
  m.walls.push_back(test::plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0));
  m.walls.push_back(test::plane({0.0, 0.0, 10.0 * kR}, {0.0, 0.0, -1.0}, 0));
  m.damping.particle = 0.5;
  m.finalize();
  c.k_n = m.bonds.stiffness[0].k_n;
  return c;
}

double compressed_force(BondedContacts mode, double travel, double* expected) {
  Column c = column(mode);
  // The column's lowest mode has a period ~1e-3 s; the lid takes 0.02 s for its travel. At twice
  // this speed the force is ~0.9 % off (residual dynamics), here 0.2 %.
  const double speed = 1e-3;  // m/s
  c.model.walls[1].velocity = {0.0, 0.0, -speed};
  Simulation sim(c.model, 1e-6);  // omega dt ~ 0.03 for the stiffest contact
  while (sim.time() < travel / speed) sim.step();
  const double d = -c.model.walls[1].displacement.z;
  const double e_star = kE / (2.0 * (1.0 - kNu * kNu));  // same material on both sides
  auto hertz = [&](double r_star, double delta) { return 4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(delta, 1.5); };
  auto link = [&](double f) {
    return solve([&](double x) { return c.k_n * x + (mode == BondedContacts::superimpose ? hertz(0.5 * kR, x) : 0.0) - f; },
                 0.0, f / c.k_n);
  };
  auto wall = [&](double f) { return std::pow(3.0 * f / (4.0 * e_star * std::sqrt(kR)), 2.0 / 3.0); };
  *expected = solve([&](double f) { return 2.0 * wall(f) + 4.0 * link(f) - d; }, 0.0, c.k_n * d);
  return -dot(c.model.walls[1].force, c.model.walls[1].normal);
}

TEST(CompressionTest, ReplacedContactsBondsAndWallsInSeries) {
  double expected = 0.0;
  const double f = compressed_force(BondedContacts::replace, 2e-5, &expected);
  EXPECT_NEAR(f / expected, 1.0, 0.01);
  RecordProperty("force_ratio", std::to_string(f / expected));
}

TEST(CompressionTest, SuperimposedContactsStiffenEachLink) {
  double replaced = 0.0, expected = 0.0;
  compressed_force(BondedContacts::replace, 2e-5, &replaced);
  const double f = compressed_force(BondedContacts::superimpose, 2e-5, &expected);
  EXPECT_NEAR(f / expected, 1.0, 0.01);
  RecordProperty("force_ratio", std::to_string(f / expected));
  RecordProperty("stiffening", std::to_string(expected / replaced));
  EXPECT_GT(expected, 1.5 * replaced);  // the particle contacts carry a large share
}

}  // namespace
}  // namespace bpm
