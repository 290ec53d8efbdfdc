// Thread-count invariance of the contact and wall loops (contact_forces.hpp: per-pair slots, then a
// gather in pair order; walls: per-particle slots, block sums in order): 5184 colliding spheres with friction and rolling friction in a cylinder between a floor and a
// moving lid, under gravity, 40 steps with 1 and 2 OpenMP threads; positions, velocities, spins,
// contact forces and wall forces must be bitwise identical.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <random>
#include <vector>

#include "contact_helpers.hpp"
#include "dem/contact_time_step.hpp"
#include "core/parallel.hpp"
#include "dem/simulation.hpp"

namespace bpm {
namespace {

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

Model cloud() {
  // 18 x 18 x 16 = 5184 spheres of radius 0.7-1 mm on a 2.05 mm lattice jittered by +-0.05 mm (no
  // initial overlaps), random velocities up to 1 m/s: many collisions, no explosion.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Model model;
  for (int i = 0; i < 18; ++i) {
    for (int j = 0; j < 18; ++j) {
      for (int k = 0; k < 16; ++k) {
        const Vec3 x{2.05e-3 * (i + 0.5) + 5e-5 * u(rng), 2.05e-3 * (j + 0.5) + 5e-5 * u(rng),
                     2.05e-3 * (k + 0.5) + 5e-5 * u(rng)};
        const std::int32_t p = model.particles.add((i * 18 + j) * 16 + k, x, 0.85e-3 + 0.15e-3 * u(rng), 2500.0);
        model.particles.velocity[p] = {u(rng), u(rng), u(rng)};
        model.particles.angular_velocity[p] = {500.0 * u(rng), 500.0 * u(rng), 500.0 * u(rng)};
      }
    }
  }
  model.contacts.particle_particle = true;
  model.contacts.materials = {test::hertz_material(1e6, 0.3, 0.5, 0.5, 0.05)};
  model.contacts.skin = 0.3e-3;  // lists the lattice neighbours; rebuilt every few steps
  model.gravity = {0.0, 0.0, -9.81};
  model.walls.push_back(test::plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0));
  Wall lid = test::plane({0.0, 0.0, 0.0328}, {0.0, 0.0, -1.0}, 0);
  lid.velocity = {0.0, 0.0, -0.5};
  model.walls.push_back(lid);
  Wall cylinder;
  cylinder.shape = WallShape::cylinder;
  cylinder.point = {0.01845, 0.01845, 0.0};
  cylinder.normal = {0.0, 0.0, 1.0};
  cylinder.radius = 0.0265;  // encloses the lattice (half diagonal 26.1 mm)
  model.walls.push_back(cylinder);
  model.finalize();
  return model;
}

struct State {
  std::vector<Vec3> position, velocity, angular_velocity, contact_force, walls;
  std::int64_t builds = 0;
  std::int64_t touching = 0;
};

State run_with_threads(int threads) {
  Model model = cloud();
  const double dt = 0.5 * contact_time_step(model, 0.1).critical;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  Simulation sim(model, dt);
  for (int s = 0; s < 40; ++s) sim.step();
  omp_set_num_threads(saved);
  State out{model.particles.position, model.particles.velocity, model.particles.angular_velocity,
            sim.contacts().force(), {}, sim.contacts().list().builds(), sim.contacts().touching()};
  for (const Wall& w : model.walls) out.walls.push_back(w.force);
  return out;
}

TEST(ContactThreadsTest, BitwiseIdenticalFor1And2Threads) {
  const State one = run_with_threads(1);
  ASSERT_GT(static_cast<std::int64_t>(one.position.size()), kParallelMinItems);
  ASSERT_GT(static_cast<std::int64_t>(one.contact_force.size()), kParallelMinItems);
  ASSERT_GT(one.touching, 100);
  ASSERT_GT(one.builds, 1);
  ASSERT_GT(norm(one.walls[0]) + norm(one.walls[2]), 0.0);
  const State two = run_with_threads(2);
  EXPECT_TRUE(bitwise_equal(one.position, two.position));
  EXPECT_TRUE(bitwise_equal(one.velocity, two.velocity));
  EXPECT_TRUE(bitwise_equal(one.angular_velocity, two.angular_velocity));
  EXPECT_TRUE(bitwise_equal(one.contact_force, two.contact_force));
  EXPECT_TRUE(bitwise_equal(one.walls, two.walls));
  EXPECT_EQ(one.builds, two.builds);
}

}  // namespace
}  // namespace bpm
