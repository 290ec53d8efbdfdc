// The Verlet list equals the brute-force O(N^2) list on a random polydisperse cloud, is the same
// for 1 and 2 threads, is rebuilt exactly when some particle has moved more than half the skin, and
// carries the tangential springs of surviving pairs over a rebuild.
#include <gtest/gtest.h>
#include <omp.h>

#include <utility>
#include <vector>

#include "contact_helpers.hpp"
#include "contacts/contact_forces.hpp"
#include "contacts/neighbour_list.hpp"
#include "core/parallel.hpp"

namespace bpm {
namespace {

std::vector<std::pair<std::int32_t, std::int32_t>> pairs_of(const NeighbourList& list) {
  std::vector<std::pair<std::int32_t, std::int32_t>> out;
  for (std::size_t k = 0; k < list.size(); ++k) out.emplace_back(list.first()[k], list.second()[k]);
  return out;
}

std::vector<std::pair<std::int32_t, std::int32_t>> brute_force(const ParticleStore& p, double skin) {
  std::vector<std::pair<std::int32_t, std::int32_t>> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (norm(p.position[j] - p.position[i]) - p.radius[i] - p.radius[j] < skin) {
        out.emplace_back(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
      }
    }
  }
  return out;
}

NeighbourList build_with_threads(const ParticleStore& p, double skin, int threads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  NeighbourList list;
  list.build(p.position, p.radius, skin);
  omp_set_num_threads(saved);
  return list;
}

TEST(NeighbourListTest, EqualsBruteForceAndIsThreadCountIndependent) {
  // 6000 spheres (more than kParallelMinItems, so the build runs in parallel), radii 0.5-2 mm, in a
  // 5 cm box, with one far outlier that stretches the bounding box.
  Model model = test::random_cloud(6000, 0.05, 0.5e-3, 2e-3, 0.0, 0.0, 3);
  model.particles.add(6000, {0.5, -0.3, 0.2}, 1e-3, 2500.0);
  const ParticleStore& p = model.particles;
  ASSERT_GT(static_cast<std::int64_t>(p.size()), kParallelMinItems);
  const double skin = 0.2e-3;
  const NeighbourList one = build_with_threads(p, skin, 1);
  const NeighbourList two = build_with_threads(p, skin, 2);
  const auto expected = brute_force(p, skin);
  ASSERT_GT(expected.size(), 10000u);
  EXPECT_EQ(pairs_of(one), expected);  // same pairs, sorted by (i, j)
  EXPECT_EQ(pairs_of(two), expected);
  EXPECT_EQ(one.row_start(), two.row_start());
}

TEST(NeighbourListTest, RebuildsOnceAParticleHasMovedHalfTheSkin) {
  Model model = test::random_cloud(200, 0.02, 0.5e-3, 1e-3, 0.0, 0.0, 5);
  std::vector<Vec3> x = model.particles.position;
  const double skin = 1e-4;
  NeighbourList list;
  EXPECT_TRUE(list.needs_rebuild(x));
  list.build(x, model.particles.radius, skin);
  EXPECT_FALSE(list.needs_rebuild(x));
  x[17] += Vec3{0.3, 0.4, 0.0} * (0.49 * skin / 0.5);
  EXPECT_FALSE(list.needs_rebuild(x));
  x[17] = model.particles.position[17] + Vec3{0.0, 0.6, 0.8} * (0.51 * skin);
  EXPECT_TRUE(list.needs_rebuild(x));
}

TEST(NeighbourListTest, TangentialSpringsSurviveARebuild) {
  // Two touching spheres sheared past each other, plus a third one far away that is moved to force
  // rebuilds; the shear spring must be carried over unchanged.
  Model model;
  const double r = 1e-3;
  model.particles.add(0, {0.0, 0.0, 0.0}, r, 2500.0);
  model.particles.add(1, {0.05, 0.0, 0.0}, r, 2500.0);
  model.particles.add(2, {2.0 * r - 1e-5, 0.0, 0.0}, r, 2500.0);  // touches particle 0
  model.particles.velocity[2] = {0.0, 0.01, 0.0};
  model.finalize();
  ContactModel cm;
  cm.particle_particle = true;
  cm.materials = {test::hertz_material(1e8, 0.3, 0.5, 0.5)};
  cm.skin = 1e-4;
  const ContactTable table(cm);
  ContactForces contacts(table, model.particles, cm.skin);
  EXPECT_TRUE(contacts.update_list(model.particles, model.bonds));
  for (int s = 0; s < 10; ++s) contacts.compute(model.particles, model.bonds, 1e-6, 1e-6);
  ASSERT_EQ(contacts.list().size(), 1u);
  const Vec3 spring = contacts.spring()[0];
  ASSERT_GT(norm(spring), 0.0);
  EXPECT_NEAR(spring.y, 10 * 1e-6 * 0.01, 1e-15);  // v_t dt per step, sticking
  // Moved next to both (gap skin/2, not touching): now a candidate of both, so the list changes.
  const double half = 0.5 * model.particles.position[2].x, d = 2.0 * r + 0.5 * cm.skin;
  model.particles.position[1] = {half, std::sqrt(d * d - half * half), 0.0};
  EXPECT_TRUE(contacts.update_list(model.particles, model.bonds));
  ASSERT_EQ(contacts.list().size(), 3u);
  EXPECT_EQ(contacts.list().first()[1], 0);
  EXPECT_EQ(contacts.list().second()[1], 2);
  EXPECT_TRUE(contacts.spring()[1] == spring);
  EXPECT_TRUE(contacts.spring()[0] == Vec3{});
  EXPECT_TRUE(contacts.spring()[2] == Vec3{});
}

}  // namespace
}  // namespace bpm
