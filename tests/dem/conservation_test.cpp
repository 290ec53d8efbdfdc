// Conservation laws of the undamped DEM (velocity Verlet + incremental bond law) on a free bonded pair
// and a free 5-particle chain with random velocities and spins, no fixed DOFs, no loads:
// - linear momentum sum m v and angular momentum sum (m x cross v + I omega) to round-off: the bond
//   law applies equal and opposite forces and moments that balance about any point (arms sum to L);
// - total energy (kinetic + elastic) to a stated tolerance, with an error of second order in dt.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "common/bond_model_keys.hpp"
#include "dem/time_step.hpp"
#include "dem_helpers.hpp"

namespace bpm {
namespace {

using test::model_keys;

struct Case {
  std::string key;
  int particles;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  for (const std::string& key : model_keys()) {
    c.push_back({key, 2});
    c.push_back({key, 5});
  }
  return c;
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.key << " x" << c.particles; }

class ConservationTest : public ::testing::TestWithParam<Case> {};

// Small amplitude: velocities of 1 cm/s (strain ~ v / c ~ 2e-6) and spins of 10 rad/s.
constexpr double kSpeed = 0.01, kSpin = 10.0;

TEST_P(ConservationTest, MomentumToRoundOff) {
  Model model = test::free_chain(GetParam().particles, GetParam().key, kSpeed, kSpin, 11);
  const double dt = 0.5 * critical_time_step(model).critical;
  Simulation sim(model, dt);
  const ParticleStore& p = model.particles;
  const Vec3 P0 = test::linear_momentum(p), L0 = test::angular_momentum(p);
  const double p_scale = test::momentum_scale(p), l_scale = test::angular_momentum_scale(p);
  double p_err = 0.0, l_err = 0.0;
  for (int s = 0; s < 10000; ++s) {
    sim.step();
    p_err = std::max(p_err, norm(test::linear_momentum(p) - P0) / p_scale);
    l_err = std::max(l_err, norm(test::angular_momentum(p) - L0) / l_scale);
  }
  EXPECT_LT(p_err, 1e-12) << "linear momentum";
  EXPECT_LT(l_err, 1e-12) << "angular momentum";
  EXPECT_GT(sim.energies().elastic, 0.0) << "the bonds were never loaded: the test would be vacuous";
}

/// Largest |E(t) - E(0)| / E(0) over `time` with step dt.
double energy_error(const Case& c, double dt_fraction, double time) {
  Model model = test::free_chain(c.particles, c.key, kSpeed, kSpin, 5);
  const double dt = dt_fraction * critical_time_step(model).critical;
  Simulation sim(model, dt);
  const double e0 = test::total_energy(sim);
  double err = 0.0;
  const auto steps = static_cast<long>(std::llround(time / dt));
  for (long s = 0; s < steps; ++s) {
    sim.step();
    err = std::max(err, std::abs(test::total_energy(sim) - e0) / e0);
  }
  return err;
}

// Measured (GCC 12, -O2, these seeds): the largest relative energy error over 1e4 steps at
// dt = critical/20 is 2.2e-4 (5 particles) to 6.6e-4 (pairs); at critical/40 over the same time
// 5.6e-5 to 1.65e-4; the ratio is 4.00 +- 0.03 in all ten cases. Asserted: < 1e-3, < 2.5e-4, 4 +- 0.3.
TEST_P(ConservationTest, EnergyConservedAndSecondOrder) {
  Model probe = test::free_chain(GetParam().particles, GetParam().key, kSpeed, kSpin, 5);
  const double time = 1e4 * critical_time_step(probe).critical / 20.0;
  const double coarse = energy_error(GetParam(), 1.0 / 20.0, time);
  const double fine = energy_error(GetParam(), 1.0 / 40.0, time);
  RecordProperty("energy_error_dt", std::to_string(coarse));
  RecordProperty("energy_error_dt_half", std::to_string(fine));
  EXPECT_LT(coarse, 1e-3);
  EXPECT_LT(fine, 2.5e-4);
  EXPECT_GT(fine, 0.0);
  // Velocity Verlet: halving dt divides the energy error by 4 (2 would mean a first-order defect).
  EXPECT_NEAR(coarse / fine, 4.0, 0.3) << "coarse " << coarse << ", fine " << fine;
}

INSTANTIATE_TEST_SUITE_P(Chains, ConservationTest, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& param_info) {
                           return param_info.param.key + "_" + std::to_string(param_info.param.particles);
                         });

// -------------------------------------------------------------------------------------------------
// Known defect (see the report of the tests/dem work): the kernel projects the step's relative
// translation (a chord, (x_new - x_old)/dt from the integrator) onto the END-of-step axis. Under a
// rigid rotation by phi per step the chord has an axial part L (1 - cos phi) on that axis although
// the length does not change, so the stored normal force ratchets by k_n L phi^2 / 2 per step: a
// spinning pair shortens its bond by a strain -Theta phi / 2 after turning Theta radians, and the
// energy error becomes first order in dt. Projecting onto the mid-step axis (n_old + n_new)/|..|
// removes it (the chord of a rotation is orthogonal to that axis). Enable once fixed.

struct SpinResult {
  double force_error;   ///< |F_n - k_n (L - L0)| / (centripetal force m Omega^2 L / 2)
  double energy_error;  ///< |E - E0| / E0 after two revolutions
};

SpinResult spin_pair(double dt_fraction) {
  Model model;
  const double R = 1e-3, L = 2e-3, omega = 2000.0;  // rim speed 2 m/s
  model.particles.add(0, {-0.5 * L, 0.0, 0.0}, R, 7850.0);
  model.particles.add(1, {0.5 * L, 0.0, 0.0}, R, 7850.0);
  test::bond(model, 0, 1, test::steel_bond("tbbm"));
  const Vec3 spin{0.0, 0.0, omega};
  for (int i = 0; i < 2; ++i) {
    model.particles.velocity[i] = cross(spin, model.particles.position[i]);
    model.particles.angular_velocity[i] = spin;
  }
  model.finalize();
  const double dt = dt_fraction * critical_time_step(model).critical;
  Simulation sim(model, dt);
  const double e0 = test::total_energy(sim);
  const auto steps = static_cast<long>(4.0 * std::numbers::pi / omega / dt);
  for (long s = 0; s < steps; ++s) sim.step();
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  const double length = norm(p.position[1] - p.position[0]);
  const double f_n = dot(b.force[0], b.axis[0]);
  const double centripetal = p.mass[0] * omega * omega * 0.5 * length;
  return {std::abs(f_n - b.stiffness[0].k_n * (length - b.rest_length[0])) / centripetal,
          std::abs(test::total_energy(sim) - e0) / e0};
}

TEST(SpinningPairTest, RigidSpinLeavesBondLengthAndEnergy) {
  // Measured with the current kernel at dt = 0.4 critical (Omega dt = 3.7e-4): force error 1.1e4
  // times the centripetal force (bond strain -2.3e-3), energy error 3.3e-3, halving with dt (2.0).
  // With the mid-step axis: force error < 1e-6, energy error 2e-8.
  const SpinResult coarse = spin_pair(0.4), fine = spin_pair(0.2);
  EXPECT_LT(coarse.force_error, 1e-3);
  EXPECT_LT(coarse.energy_error, 1e-6);
  EXPECT_LT(fine.energy_error, 1e-6);
}

}  // namespace
}  // namespace bpm
