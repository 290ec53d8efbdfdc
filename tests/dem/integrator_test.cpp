// The explicit loop (src/dem/simulation.*) beyond the bond law: particle damping to rest and the static
// answer, bond damping dissipation, gravity, prescribed velocities, load ramps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dem/time_step.hpp"
#include "dem_helpers.hpp"
#include "statics/static_solver.hpp"
#include "verify/cantilever.hpp"

namespace bpm {
namespace {

TEST(ParticleDampingTest, LoadedCantileverComesToRestAtTheStaticSolution) {
  // Chen case 1 (11 particles, TBBM, F = 100 kN at the tip), the ramp shortened to 0.05 s to keep the
  // test short, gamma_b = 0.7, rest at max speed < 1e-9 m/s (Chen's criterion).
  verify::CantileverSpec spec = verify::cantilever_case(1).front();
  spec.ramp_time = 0.05;
  Model model = verify::build_cantilever(spec, "tbbm", 0.7);
  const StaticSolution exact = solve_linear_static(model);  // at the undeformed positions
  Simulation sim(model, 0.8 * critical_time_step(model).critical);
  StopCriteria stop;
  stop.rest_speed = 1e-9;
  stop.rest_after = spec.ramp_time;
  stop.end_time = 60.0;
  const RunSummary summary = sim.run(stop);
  ASSERT_EQ(summary.reason, StopReason::rest) << "t = " << summary.time << ", max speed " << summary.max_speed;
  EXPECT_LT(summary.max_speed, 1e-9);
  const ParticleStore& p = model.particles;
  const double tip = -exact.displacement.back().y;
  EXPECT_NEAR(tip, 8.534242e-3, 1e-6 * tip);
  // Deflection and rotation: the DEM's steady state is the linear static solution up to the geometric
  // nonlinearity of rotations ~3e-3 rad (measured 4.6e-6 of the tip deflection); 1e-5 asserted.
  const double tip_rotation = std::abs(exact.rotation.back().z);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 u = p.position[i] - p.reference_position[i];
    EXPECT_NEAR(u.y, exact.displacement[i].y, 1e-5 * tip) << "particle " << i;
    EXPECT_NEAR(u.z, 0.0, 1e-12 * tip) << "particle " << i;
    const Vec3 theta = rotation_vector(p.orientation[i]);
    EXPECT_NEAR(theta.z, exact.rotation[i].z, 1e-5 * tip_rotation) << "particle " << i;
    EXPECT_NEAR(norm(Vec3{theta.x, theta.y, 0.0}), 0.0, 1e-12 * tip_rotation) << "particle " << i;
  }
  // Along the axis the linear solution has no displacement; the DEM shortens by the second-order
  // arc-length effect of the bending rotation, -1/2 int theta^2 dx = -F^2 L^5 / (15 (E I)^2)
  // = -1.081e-5 m (measured -1.087e-5: shear and stretch add the rest).
  const double EI = 200e9 * 0.25 * std::numbers::pi * std::pow(0.2, 4);
  const double shortening = -1e10 * std::pow(4.0, 5) / (15.0 * EI * EI);
  EXPECT_NEAR(p.position.back().x - p.reference_position.back().x, shortening, 0.02 * std::abs(shortening));
  // At rest the beam passes the whole tip load to the clamped particle (whose support reaction is
  // implicit in its fixed DOFs): a force of -100 kN in y and the moment 4 m x (-100 kN) = -4e5 N m
  // about z.
  EXPECT_NEAR(p.force[0].y, -1e5, 1e-3 * 1e5);
  EXPECT_NEAR(p.torque[0].z, -4e5, 1e-3 * 4e5);
}

TEST(ParticleDampingTest, SmallLoadMatchesLinearSolutionClosely) {
  // At 1 % of the load the geometric terms drop by 100 (linear part) and 1e4 (shortening).
  verify::CantileverSpec spec = verify::cantilever_case(1).front();
  spec.ramp_time = 0.05;
  spec.load *= 0.01;
  Model model = verify::build_cantilever(spec, "tbbm", 0.7);
  const StaticSolution exact = solve_linear_static(model);
  Simulation sim(model, 0.8 * critical_time_step(model).critical);
  StopCriteria stop;
  stop.rest_speed = 1e-11;
  stop.rest_after = spec.ramp_time;
  stop.end_time = 60.0;
  ASSERT_EQ(sim.run(stop).reason, StopReason::rest);
  const double tip = -exact.displacement.back().y;
  for (std::size_t i = 0; i < model.particles.size(); ++i) {
    const Vec3 u = model.particles.position[i] - model.particles.reference_position[i];
    EXPECT_LE(norm(u - exact.displacement[i]), 2e-5 * tip) << "particle " << i;  // measured 1.3e-5
    EXPECT_NEAR(u.y, exact.displacement[i].y, 3e-7 * tip) << "particle " << i;  // measured 6e-8
  }
}

TEST(BondDampingTest, FreePairOscillationLosesEnergyMonotonically) {
  // A free pair set vibrating with zero total momentum and angular momentum (so that no rigid-body
  // energy is left for the damping to leave alone): stretching, twisting and bending velocities split
  // in inverse proportion to the masses/inertias. eta_b = 0.2. E = kinetic + elastic, every step.
  Model model = test::free_chain(2, "tbbm", 0.0, 0.0, 4);
  ParticleStore& p = model.particles;
  const Vec3 n = model.bonds.axis[0];
  const Vec3 e1 = cross(n, Vec3{0.0, 0.0, 1.0}) / norm(cross(n, Vec3{0.0, 0.0, 1.0}));
  const double m0 = p.mass[0], m1 = p.mass[1], i0 = p.inertia[0], i1 = p.inertia[1];
  const Vec3 stretch = 0.02 * n, spin = 30.0 * n + 20.0 * e1;
  p.velocity[0] = -(m1 / (m0 + m1)) * stretch;
  p.velocity[1] = (m0 / (m0 + m1)) * stretch;
  p.angular_velocity[0] = -(i1 / (i0 + i1)) * spin;
  p.angular_velocity[1] = (i0 / (i0 + i1)) * spin;
  model.damping.bond = 0.2;
  model.finalize();
  Simulation sim(model, 0.05 * critical_time_step(model).critical);
  const double e0 = test::total_energy(sim);
  double previous = e0;
  double worst_rise = 0.0;
  for (int s = 0; s < 20000; ++s) {
    sim.step();
    const double e = test::total_energy(sim);
    worst_rise = std::max(worst_rise, (e - previous) / e0);
    previous = e;
  }
  // Round-off aside (measured rises <= 1e-14 E0), the energy never increases.
  EXPECT_LE(worst_rise, 1e-12) << "energy rose in some step by " << worst_rise << " E0";
  EXPECT_LT(previous, 1e-3 * e0) << "bond damping removed too little energy";
  // Internal damping leaves the momenta alone.
  EXPECT_LE(norm(test::linear_momentum(p)), 1e-12 * 0.02 * m0);
}

TEST(GravityTest, FreeParticleFallsExactly) {
  // Velocity Verlet integrates a constant acceleration exactly: x = x0 + g t^2 / 2, v = g t.
  Model model;
  model.particles.add(0, {0.1, 0.2, 0.3}, 1e-3, 2500.0);
  model.gravity = {0.5, -9.81, 0.0};
  model.finalize();
  const double dt = 1e-3;
  Simulation sim(model, dt);
  const ParticleStore& p = model.particles;
  for (int s = 1; s <= 2000; ++s) {
    sim.step();
    const double t = s * dt;
    const Vec3 x = Vec3{0.1, 0.2, 0.3} + (0.5 * t * t) * model.gravity;
    EXPECT_LE(norm(p.position[0] - x), 1e-13 * norm(x)) << "step " << s;
    EXPECT_LE(norm(p.velocity[0] - t * model.gravity), 1e-13 * t * 9.81) << "step " << s;
  }
  EXPECT_EQ(norm(p.angular_velocity[0]), 0.0);
}

TEST(PrescribedMotionTest, FixedParticleMovesAtItsPrescribedVelocity) {
  // Particle 0 has all DOFs fixed and a prescribed velocity and spin; the bond to particle 1 loads it
  // every step, yet it keeps its velocity exactly and drags particle 1 along.
  Model model = test::free_chain(2, "tbbm", 0.0, 0.0, 8, {0.0, 0.0, 0.0});
  model.fix(0, {1, 1, 1}, {1, 1, 1});
  ParticleStore& p = model.particles;
  const Vec3 v{0.05, -0.02, 0.01}, w{0.0, 0.0, 2.0};
  p.velocity[0] = v;
  p.angular_velocity[0] = w;
  const Vec3 x0 = p.position[0], x1 = p.position[1];
  const double dt = 0.5 * critical_time_step(model).critical;
  Simulation sim(model, dt);
  double largest_load = 0.0;
  for (int s = 1; s <= 20000; ++s) {
    sim.step();
    largest_load = std::max(largest_load, norm(p.force[0]));
    ASSERT_EQ(p.velocity[0], v) << "step " << s;
    ASSERT_EQ(p.angular_velocity[0], w) << "step " << s;
  }
  const double t = sim.time();
  EXPECT_LE(norm(p.position[0] - (x0 + t * v)), 1e-12 * norm(x0 + t * v));
  EXPECT_LE(norm(rotation_vector(p.orientation[0]) - t * w), 1e-12);
  EXPECT_GT(largest_load, 0.0) << "the bond never pulled on the prescribed particle";
  // The follower was carried along rigidly: translated by v t and swung about particle 0 by w t
  // (up to the bond's small elastic vibration, strain ~ |v| / c ~ 1e-5).
  const Vec3 r = x1 - x0, k = w / norm(w);
  const double a = norm(w) * t;
  const Vec3 swung = std::cos(a) * r + std::sin(a) * cross(k, r) + (1.0 - std::cos(a)) * dot(k, r) * k;
  EXPECT_LT(norm((p.position[1] - x1) - (t * v + swung - r)), 1e-2 * norm(t * v));
}

TEST(LoadRampTest, FactorRampsLinearlyThenHolds) {
  Load load{{0}, {1.0, 0.0, 0.0}, {}, 2.0};
  EXPECT_EQ(load.factor(0.0), 0.0);
  EXPECT_DOUBLE_EQ(load.factor(0.5), 0.25);
  EXPECT_DOUBLE_EQ(load.factor(1.5), 0.75);
  EXPECT_EQ(load.factor(2.0), 1.0);
  EXPECT_EQ(load.factor(7.0), 1.0);
  load.ramp_time = 0.0;
  EXPECT_EQ(load.factor(0.0), 1.0);
}

TEST(LoadRampTest, RampedLoadOnFreeParticle) {
  // F(t) = F t / T on a free particle: the applied force follows the ramp exactly at every step, the
  // velocity (trapezoidal in the acceleration) is exact for a linear ramp, v = F t^2 / (2 m T), and the
  // position is second-order accurate, x = F t^3 / (6 m T) + O(dt^2).
  Model model;
  model.particles.add(0, {}, 1e-3, 2500.0);
  const Vec3 F{2e-3, -1e-3, 0.0}, M{0.0, 0.0, 1e-9};
  const double T = 0.1, dt = 1e-4;
  model.loads.push_back({{0}, F, M, T});
  model.finalize();
  Simulation sim(model, dt);
  const ParticleStore& p = model.particles;
  const double m = p.mass[0], I = p.inertia[0];
  for (int s = 1; s <= 2000; ++s) {  // to 2 T: ramp, then hold
    sim.step();
    const double t = sim.time();
    EXPECT_EQ(p.force[0], model.loads[0].factor(t) * F) << "step " << s;
    if (t <= T + 1e-12) {
      const Vec3 v = (t * t / (2.0 * m * T)) * F;
      EXPECT_LE(norm(p.velocity[0] - v), 1e-12 * norm(F) * T / m) << "step " << s;
      EXPECT_NEAR(p.angular_velocity[0].z, t * t / (2.0 * I * T) * M.z, 1e-12 * M.z * T / I) << "step " << s;
      const Vec3 x = (t * t * t / (6.0 * m * T)) * F;
      EXPECT_LE(norm(p.position[0] - x), 1e-12 * norm(F) * T * T / m + (dt * dt) * t / (6.0 * m * T) * norm(F) * 2.0)
          << "step " << s;
    }
  }
  // After the ramp the load is held: v grows linearly with slope F / m.
  const double t = sim.time();
  EXPECT_LE(norm(p.velocity[0] - (T / (2.0 * m) + (t - T) / m) * F), 1e-10 * norm(F) * t / m);
}

}  // namespace
}  // namespace bpm
