// Bond breakage (bonds/bond_strength.hpp, dem/bond_forces.cpp): a bonded pair driven kinematically
// breaks exactly when the parallel-bond stress reaches its strength, in the right mode, for each
// load type (tension, shear force, twist, bending, tension plus bending); compression never breaks
// a bond in tension; a ramped DEM load breaks it at the analytical load; strengths drawn from normal
// and Weibull distributions have the requested moments and are reproducible; the break log is the
// same for any thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <string>

#include "dem/bond_forces.hpp"
#include "dem/time_step.hpp"
#include "dem_helpers.hpp"

namespace bpm {
namespace {

constexpr double kTensile = 20e6;  // sigma_t, Pa
constexpr double kShear = 30e6;    // tau_s, Pa

BondMaterial breakable(const std::string& key) {
  BondMaterial m = test::steel_bond(key);
  m.tensile_strength.value = kTensile;
  m.shear_strength.value = kShear;
  return m;
}

/// A pair along x, alpha clamped, beta moved by the test; R = 1 mm, r_b = 0.8 mm.
struct Pair {
  Model model;
  double r_b = 0.0, area = 0.0, inertia = 0.0;  // r_b, A_b, I_b
  BondStiffness k;

  explicit Pair(const std::string& key) {
    model.particles.add(0, {0.0, 0.0, 0.0}, 1e-3, 7850.0);
    model.particles.add(1, {2e-3, 0.0, 0.0}, 1e-3, 7850.0);
    test::bond(model, 0, 1, breakable(key));
    model.bonds.draw_strengths({breakable(key)}, 1);
    model.fix(0, {1, 1, 1}, {1, 1, 1});
    model.finalize();
    r_b = model.bonds.radius[0];
    area = std::numbers::pi * r_b * r_b;
    inertia = 0.25 * std::numbers::pi * std::pow(r_b, 4);
    k = model.bonds.stiffness[0];
  }

  /// Moves beta by (du, dtheta) per step until the bond breaks; returns the step that broke it.
  int drive(const Vec3& du, const Vec3& dtheta, int max_steps = 100000) {
    const double dt = 1e-7;
    ParticleStore& p = model.particles;
    for (int s = 1; s <= max_steps; ++s) {
      p.position[1] += du;
      p.velocity[1] = du / dt;
      p.angular_velocity[1] = dtheta / dt;
      update_bond_loads(p, model.bonds, dt);
      if (model.bonds.intact[0] == 0) return s;
    }
    return -1;
  }
};

class BreakageTest : public ::testing::TestWithParam<std::string> {};

/// Loads grow by kPerStep of their limit per step, so the bond should break at step 1/kPerStep + 1
/// (the first step beyond the limit). One step either way is 0.1 % of the break load: the margin for
/// round-off at the threshold and for the geometric (second-order) terms of the finite motion.
constexpr double kPerStep = 1e-3;
void expect_breaks_at(int step, double fraction_per_step) {
  EXPECT_NEAR(step, std::floor(1.0 / fraction_per_step) + 1.0, 1.0);
}

void expect_broken(const Pair& pair, BreakMode mode) {
  const BondStore& b = pair.model.bonds;
  ASSERT_EQ(b.breaks.size(), 1u);
  EXPECT_EQ(b.breaks[0].mode, mode);
  EXPECT_EQ(b.breaks[0].bond, 0);
  EXPECT_EQ(norm(b.force[0]) + norm(b.moment[0]), 0.0) << "a broken bond carries no load";
  EXPECT_EQ(norm(b.end_force_alpha[0]) + norm(b.end_moment_beta[0]), 0.0);
  EXPECT_EQ(b.intact_count(), 0u);
}

TEST_P(BreakageTest, TensionBreaksAtTensileStrength) {
  Pair pair(GetParam());
  const double du = kPerStep * kTensile * pair.area / pair.k.k_n;
  expect_breaks_at(pair.drive({du, 0.0, 0.0}, {}), kPerStep);
  expect_broken(pair, BreakMode::tension);
  // The break is logged at the contact point, between the two centres.
  EXPECT_GT(pair.model.bonds.breaks[0].position.x, 0.9e-3);
  EXPECT_LT(pair.model.bonds.breaks[0].position.x, 1.1e-3);
}

TEST_P(BreakageTest, CompressionDoesNotBreakInTension) {
  Pair pair(GetParam());
  const double du = kPerStep * kTensile * pair.area / pair.k.k_n;
  EXPECT_EQ(pair.drive({-du, 0.0, 0.0}, {}, 5000), -1) << "5x the tensile load in compression";
}

TEST_P(BreakageTest, ShearForceBreaksAtShearStrength) {
  // A transverse translation of beta with no rotation loads the contact point in pure shear:
  // tau = |F_s| / A_b.
  Pair pair(GetParam());
  const double du = kPerStep * kShear * pair.area / pair.k.k_s;
  expect_breaks_at(pair.drive({0.0, du, 0.0}, {}), kPerStep);
  expect_broken(pair, BreakMode::shear);
}

TEST_P(BreakageTest, TwistBreaksAtShearStrength) {
  // tau = M_tor r_b / J_b, J_b = 2 I_b.
  Pair pair(GetParam());
  const double limit = kShear * 2.0 * pair.inertia / pair.r_b;
  expect_breaks_at(pair.drive({}, {kPerStep * limit / pair.k.k_tor, 0.0, 0.0}), kPerStep);
  expect_broken(pair, BreakMode::shear);
}

TEST_P(BreakageTest, BendingBreaksAtTensileStrength) {
  // Rotating beta about z by phi moves its contact point by phi e_z x (-a_beta e_x) = -a_beta phi e_y;
  // moving beta's centre by +a_beta phi e_y cancels that, so the contact point sees pure bending.
  Pair pair(GetParam());
  const double limit = kTensile * pair.inertia / pair.r_b;  // sigma = M_ben r_b / I_b
  const double phi = kPerStep * limit / pair.k.k_ben;
  const double a_beta = 1e-3;  // equal radii: contact point at the middle for every model
  expect_breaks_at(pair.drive({0.0, phi * a_beta, 0.0}, {0.0, 0.0, phi}), kPerStep);
  expect_broken(pair, BreakMode::tension);
}

TEST_P(BreakageTest, TensionAndBendingAddUp) {
  // 0.6 of the limit from each, applied together: sigma reaches the strength at 1/1.2 of the path.
  Pair pair(GetParam());
  const double du = 0.6 * kPerStep * kTensile * pair.area / pair.k.k_n;
  const double phi = 0.6 * kPerStep * (kTensile * pair.inertia / pair.r_b) / pair.k.k_ben;
  expect_breaks_at(pair.drive({du, phi * 1e-3, 0.0}, {0.0, 0.0, phi}), 1.2 * kPerStep);
  expect_broken(pair, BreakMode::tension);
}

INSTANTIATE_TEST_SUITE_P(Models, BreakageTest, ::testing::Values("pbm", "ebbm", "tbbm"));

TEST(BreakageDem, RampedPullBreaksAtTheAnalyticalLoad) {
  // Beta pulled by a force ramped at a rate slow against the pair's period, with particle damping:
  // the bond force follows the load, and the bond breaks when F = sigma_t A_b.
  Pair pair("tbbm");
  const double f_break = kTensile * pair.area;
  const double ramp = 2e-3;  // s to reach 2 f_break; the axial period is ~1e-6 s
  pair.model.loads.push_back({{1}, {2.0 * f_break, 0.0, 0.0}, {}, ramp});
  pair.model.damping.particle = 0.7;
  Simulation sim(pair.model, 0.5 * critical_time_step(pair.model).critical);
  while (pair.model.bonds.intact[0] == 1 && sim.time() < ramp) sim.step();
  ASSERT_EQ(pair.model.bonds.breaks.size(), 1u);
  EXPECT_EQ(pair.model.bonds.breaks[0].mode, BreakMode::tension);
  const double load_at_break = 2.0 * f_break * sim.time() / ramp;
  EXPECT_NEAR(load_at_break / f_break, 1.0, 1e-3);
}

TEST(BondStrengths, DistributionsHaveTheirMomentsAndAreSeeded) {
  Model model = test::cubic_lattice(30, 30, 30, 1e-3, 0.0, 0.0, 0.0, 1);  // 78,300 bonds
  BondMaterial m = test::steel_bond("tbbm");
  m.tensile_strength = {StrengthDistribution::Kind::normal, 20e6, 2e6};
  m.shear_strength = {StrengthDistribution::Kind::weibull, 30e6, 5.0};
  BondStore& b = model.bonds;
  b.draw_strengths({m}, 42);
  const double n = static_cast<double>(b.size());
  double sum_t = 0, sum_t2 = 0, sum_s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double area = std::numbers::pi * b.radius[i] * b.radius[i];
    const double t = b.strength[i].tensile / area;
    sum_t += t;
    sum_t2 += t * t;
    sum_s += b.strength[i].shear / area;
  }
  const double mean_t = sum_t / n, std_t = std::sqrt(sum_t2 / n - mean_t * mean_t);
  EXPECT_NEAR(mean_t, 20e6, 4.0 * 2e6 / std::sqrt(n));  // 4 standard errors
  EXPECT_NEAR(std_t / 2e6, 1.0, 0.02);
  // Weibull mean: lambda Gamma(1 + 1/m); its standard deviation is ~0.23 of the mean for m = 5.
  const double weibull_mean = 30e6 * std::tgamma(1.0 + 1.0 / 5.0);
  EXPECT_NEAR(sum_s / n, weibull_mean, 4.0 * 0.23 * weibull_mean / std::sqrt(n));
  const std::vector<StrengthLimits> first = b.strength;
  b.draw_strengths({m}, 42);
  for (std::size_t i = 0; i < b.size(); ++i) ASSERT_EQ(b.strength[i].tensile, first[i].tensile);
  b.draw_strengths({m}, 43);
  EXPECT_NE(b.strength[0].tensile, first[0].tensile);
}

std::vector<BondStore::Break> break_lattice(int threads) {
  Model model = test::cubic_lattice(18, 18, 18, 1e-3, 0.05, 0.5, 500.0, 7);
  BondMaterial m = test::steel_bond("tbbm");
  m.tensile_strength = {StrengthDistribution::Kind::weibull, 40e6, 3.0};
  m.shear_strength = {StrengthDistribution::Kind::weibull, 60e6, 3.0};
  model.bonds.draw_strengths({m}, 3);
  model.finalize();
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  Simulation sim(model, 0.5 * critical_time_step(model).critical);
  for (int s = 0; s < 300; ++s) sim.step();
  omp_set_num_threads(saved);
  return model.bonds.breaks;
}

TEST(BreakageDem, BreakLogIsTheSameForAnyThreadCount) {
  const auto one = break_lattice(1), two = break_lattice(2);
  ASSERT_GT(one.size(), 100u) << "the run must break bonds for the comparison to mean anything";
  ASSERT_LT(one.size(), 15000u) << "... but not all of them";
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].bond, two[i].bond);
    EXPECT_EQ(one[i].update, two[i].update);
    EXPECT_EQ(one[i].mode, two[i].mode);
  }
}

}  // namespace
}  // namespace bpm
