// Thread-count invariance: a jittered bonded lattice with overlapping contacts, large enough that
// every parallel loop runs in parallel; the per-particle tensors, volumes, the sample tensor and
// the local map must be bitwise identical for 1 and 2 OpenMP threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <vector>

#include "core/parallel.hpp"
#include "dem/dem_helpers.hpp"
#include "ste/stiffness_tensor_estimation.hpp"

namespace bpm {
namespace {

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

ste::SteResult run_with_threads(const Model& model, int threads) {
  ste::SteOptions o;
  o.volumes = ste::VolumeMethod::voronoi;  // voro++ runs in parallel as well
  o.layered = true;
  o.local_map = true;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  ste::SteResult r = ste::estimate_stiffness(model, o);
  omp_set_num_threads(saved);
  return r;
}

TEST(SteThreads, BitwiseIdenticalFor1And2Threads) {
  // 17^3 = 4913 particles (> kParallelMinItems), 5 % jitter: no bond is axis-aligned and some
  // neighbours overlap (linearised Hertz contacts on top of the bonds).
  Model model = test::cubic_lattice(17, 17, 17, 1e-3, 0.05, 0.0, 0.0, 5);
  ContactMaterial m;
  m.name = "steel";
  m.youngs_modulus = 2e11;
  m.poisson_ratio = 0.3;
  model.contacts.materials = {m};
  model.contacts.particle_particle = true;
  ASSERT_GT(static_cast<std::int64_t>(model.particles.size()), kParallelMinItems);
  const ste::SteResult one = run_with_threads(model, 1);
  const ste::SteResult two = run_with_threads(model, 2);
  ASSERT_GT(one.contacts, 0u);
  EXPECT_TRUE(bitwise_equal(one.particle_stiffness, two.particle_stiffness));
  EXPECT_TRUE(bitwise_equal(one.particle_volume, two.particle_volume));
  EXPECT_TRUE(bitwise_equal(one.local->modulus, two.local->modulus));
  EXPECT_EQ(std::memcmp(one.stiffness.data(), two.stiffness.data(), sizeof(double) * 36), 0);
  EXPECT_EQ(one.layered->stiffness, two.layered->stiffness);
  EXPECT_EQ(one.youngs_modulus_axis, two.youngs_modulus_axis);
}

}  // namespace
}  // namespace bpm
