// critical_time_step (src/dem/time_step.*) against the true stability limit 2 / omega_max of velocity
// Verlet, omega_max^2 the largest eigenvalue of K u = omega^2 M u (assembled K, lumped masses and
// inertias, fixed DOFs removed), computed here with Eigen's GeneralizedSelfAdjointEigenSolver.
//
// GCC 12 with -march=native (AVX-512) reports false-positive -W(maybe-)uninitialized inside
// avx512fintrin.h for Eigen's dense GEMM kernels (GCC PR 105593, fixed in GCC 13). It is silenced for
// this file only, before any header pulls in the intrinsics, so that -Werror builds pass.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/bond_model_keys.hpp"
#include "dem/time_step.hpp"
#include "dem_helpers.hpp"
#include "statics/static_assembly.hpp"
#include "statics/static_solver.hpp"
#include "verify/cantilever.hpp"

namespace bpm {
namespace {

using test::model_keys;

/// Largest natural frequency of the free DOFs: omega^2 = largest eigenvalue of K u = omega^2 M u.
double omega_max(const Model& model) {
  const ParticleStore& p = model.particles;
  const Eigen::MatrixXd K_all = Eigen::MatrixXd(Eigen::SparseMatrix<double>(assemble_stiffness(model, 6, {})));
  std::vector<Eigen::Index> free;
  std::vector<double> mass;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 6; ++k) {
      const bool is_free = k < 3 ? p.translation_free[i][k] != 0.0 : p.rotation_free[i][k - 3] != 0.0;
      if (!is_free) continue;
      free.push_back(static_cast<Eigen::Index>(6 * i) + k);
      mass.push_back(k < 3 ? p.mass[i] : p.inertia[i]);
    }
  }
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd K(n, n), M = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index r = 0; r < n; ++r) {
    M(r, r) = mass[static_cast<std::size_t>(r)];
    for (Eigen::Index c = 0; c < n; ++c) K(r, c) = K_all(free[r], free[c]);
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M, Eigen::EigenvaluesOnly);
  return std::sqrt(eig.eigenvalues().maxCoeff());
}

class TimeStepTest : public ::testing::TestWithParam<std::string> {};

TEST_P(TimeStepTest, LimitIsNeverOptimistic) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Model chain = test::free_chain(5, GetParam(), 0.0, 0.0, seed);
    const double exact = 2.0 / omega_max(chain);
    const TimeStepLimit limit = critical_time_step(chain);
    EXPECT_LE(limit.critical, exact) << "seed " << seed;
    EXPECT_GE(limit.omega_max_bound, omega_max(chain) * (1.0 - 1e-12));
    // ... and not uselessly pessimistic either (Gershgorin over a chain is within a small factor).
    EXPECT_GT(limit.critical, 0.2 * exact) << "seed " << seed;
  }
  // With fixed DOFs: Chen's cantilever (first particle clamped) and particle damping off.
  const Model cantilever = verify::build_cantilever(verify::cantilever_case(1).front(), GetParam(), 0.0);
  EXPECT_LE(critical_time_step(cantilever).critical, 2.0 / omega_max(cantilever));
}

/// Runs `steps` steps of an undamped free chain with random velocities; returns max E / E0.
double run_chain(const std::string& key, double dt_of_limit, bool relative_to_exact, int steps) {
  Model model = test::free_chain(5, key, 0.01, 10.0, 3);
  const double dt = dt_of_limit * (relative_to_exact ? 2.0 / omega_max(model) : critical_time_step(model).critical);
  Simulation sim(model, dt);
  const double e0 = test::total_energy(sim);
  double worst = 0.0;
  for (int s = 0; s < steps; ++s) {
    sim.step();
    worst = std::max(worst, test::total_energy(sim) / e0);
  }
  return worst;
}

TEST_P(TimeStepTest, StableBelowLimitDivergesAboveTrueLimit) {
  // At 0.95 of the computed limit the energy stays within a bounded band (Verlet's shadow energy
  // oscillates, by more the closer omega dt comes to 2) over 2e4 steps.
  EXPECT_LT(run_chain(GetParam(), 0.95, false, 20000), 2.0);
  // At 3 times the TRUE limit the highest mode is amplified ~34x per step: non-finite within
  // a few hundred steps, which Simulation::step reports as std::runtime_error.
  EXPECT_THROW(run_chain(GetParam(), 3.0, true, 5000), std::runtime_error);
}

INSTANTIATE_TEST_SUITE_P(AllModels, TimeStepTest, ::testing::ValuesIn(model_keys()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) { return param_info.param; });

/// Runs a damped free chain at `fraction` of the damped limit; returns max E / E0 (throws on divergence).
double run_damped(double eta_b, double gamma_b, double fraction) {
  Model model = test::free_chain(5, "tbbm", 0.01, 10.0, 3);
  model.damping.bond = eta_b;
  model.damping.particle = gamma_b;
  model.finalize();  // recompute the bond damping coefficients
  Simulation sim(model, fraction * critical_time_step(model).critical);
  const double e0 = test::total_energy(sim);
  double worst = 0.0;
  for (int s = 0; s < 20000; ++s) {
    sim.step();
    worst = std::max(worst, test::total_energy(sim) / e0);
  }
  EXPECT_LT(test::total_energy(sim), e0) << "damping must not add energy";
  return worst;
}

TEST(TimeStepDampingTest, ParticleDampedRunAtTheDampedLimitIsStable) {
  // Particle damping gamma_b shrinks the limit by 1/sqrt(1 + gamma_b) (time_step.hpp); 0.95 of it runs
  // stably (measured: stable up to 1.27x for this chain).
  EXPECT_LT(run_damped(0.0, 0.7, 0.95), 2.0);
}

// With viscous bond damping the dashpot c_F = 2 eta_b sqrt(k_n m_bar) acts across the bond too (where
// k_s << k_n for the beams) and, through the lever arms, on the rotations, so the damping of the highest
// mode is much larger than eta_b. A limit from a modal ratio sqrt(2) eta_b alone was stable only up to
// 1.09, 0.71, 0.52 of itself for eta_b = 0.1, 0.3, 0.7 on this chain; the Gershgorin bound on the
// dashpot matrix (time_step.cpp) must hold at 0.95 for every case.
TEST(TimeStepDampingTest, BondDampedRunAtTheDampedLimitIsStable) {
  auto stable = [](double eta_b, double gamma_b) {
    try {
      return run_damped(eta_b, gamma_b, 0.95) < 2.0;
    } catch (const std::runtime_error&) {
      return false;  // diverged
    }
  };
  for (const double eta_b : {0.1, 0.3, 0.7}) {
    EXPECT_TRUE(stable(eta_b, 0.0)) << "eta_b " << eta_b << ": diverged at 0.95 of the limit";
    EXPECT_TRUE(stable(eta_b, 0.7)) << "eta_b " << eta_b << ", gamma_b 0.7: diverged at 0.95 of the limit";
  }
}

}  // namespace
}  // namespace bpm
