// Thread-count invariance (bond_forces.hpp: "results do not depend on the thread count"): a bonded
// cubic lattice large enough that every parallel loop actually runs in parallel (more particles and
// bonds than kParallelMinItems), random perturbations, 200 steps with 1, 2 and 4 OpenMP threads;
// positions, velocities, orientations and bond loads must be bitwise identical.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <vector>

#include "core/parallel.hpp"
#include "dem/time_step.hpp"
#include "dem_helpers.hpp"

namespace bpm {
namespace {

struct State {
  std::vector<Vec3> position, velocity, angular_velocity, bond_force, bond_moment;
  std::vector<Quat> orientation;
};

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

State run_with_threads(int threads) {
  // 18^3 = 5832 particles, 16524 bonds; jitter of 5 % of R so that no bond is axis-aligned.
  Model model = test::cubic_lattice(18, 18, 18, 1e-3, 0.05, 0.05, 50.0, 99);
  model.loads.push_back({{0, 17, 300}, {1.0, -2.0, 0.5}, {1e-4, 0.0, -1e-4}, 1e-5});
  model.damping.bond = 0.05;
  model.damping.particle = 0.1;
  const double dt = 0.5 * critical_time_step(model).critical;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  Simulation sim(model, dt);
  for (int s = 0; s < 200; ++s) sim.step();
  omp_set_num_threads(saved);
  const ParticleStore& p = model.particles;
  return {p.position, p.velocity, p.angular_velocity, model.bonds.force, model.bonds.moment, p.orientation};
}

TEST(ThreadInvarianceTest, LatticeBitwiseIdenticalFor1To4Threads) {
  {
    const Model probe = test::cubic_lattice(18, 18, 18, 1e-3, 0.05, 0.0, 0.0, 99);
    ASSERT_GT(static_cast<std::int64_t>(probe.particles.size()), kParallelMinItems);
    ASSERT_GT(static_cast<std::int64_t>(probe.bonds.size()), kParallelMinItems);
  }
  const State one = run_with_threads(1);
  // The run must have done something for the comparison to mean anything.
  const Model start = test::cubic_lattice(18, 18, 18, 1e-3, 0.05, 0.05, 50.0, 99);
  ASSERT_FALSE(bitwise_equal(one.position, start.particles.position));
  for (const int threads : {2, 4}) {
    const State other = run_with_threads(threads);
    EXPECT_TRUE(bitwise_equal(one.position, other.position)) << threads << " threads: positions";
    EXPECT_TRUE(bitwise_equal(one.velocity, other.velocity)) << threads << " threads: velocities";
    EXPECT_TRUE(bitwise_equal(one.angular_velocity, other.angular_velocity)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.orientation, other.orientation)) << threads << " threads: orientations";
    EXPECT_TRUE(bitwise_equal(one.bond_force, other.bond_force)) << threads << " threads: bond forces";
    EXPECT_TRUE(bitwise_equal(one.bond_moment, other.bond_moment)) << threads << " threads: bond moments";
  }
}

}  // namespace
}  // namespace bpm
