// The canonical order (model/spatial_order.hpp): the Morton key's bit layout, an order that
// depends on the particle set and not on its rows, ties by id, bonds by their lower then higher
// particle, and the stores carrying every field through the permutation (a bond's orientation and
// input row too).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "bonds/bond_model.hpp"
#include "model/bond_store.hpp"
#include "model/particle_store.hpp"
#include "model/spatial_order.hpp"

namespace bpm {
namespace {

/// Every third bit from bit 0: a cell coordinate of kMaxCell, spread.
constexpr std::uint64_t kAllX = 0x1249249249249249ULL;

TEST(MortonGrid, InterleavesTheCellsOfTheBoundingCube) {
  const MortonGrid grid = MortonGrid::around({{1, 2, 3}, {3, 3, 3.5}, {2, 2.5, 3}});
  EXPECT_EQ(grid.lower, (Vec3{1, 2, 3}));
  EXPECT_DOUBLE_EQ(grid.cells_per_metre, MortonGrid::kMaxCell / 2.0);  // the longest side, x
  EXPECT_EQ(grid.key({1, 2, 3}), 0u);
  EXPECT_EQ(grid.key({3, 2, 3}), kAllX);
  EXPECT_EQ(grid.key({1, 4, 3}), kAllX << 1);  // y in bit 1: a cube, so y reaches the last cell too
  EXPECT_EQ(grid.key({1, 2, 5}), kAllX << 2);
  EXPECT_EQ(grid.key({3, 4, 5}), kAllX | kAllX << 1 | kAllX << 2);
  // Cell 1 along x is bit 0, along z bit 2; half a cell stays in cell 0.
  const double cell = 1.0 / grid.cells_per_metre;
  EXPECT_EQ(grid.key({1 + 1.5 * cell, 2, 3}), 1u);
  EXPECT_EQ(grid.key({1, 2, 3 + 1.5 * cell}), 4u);
  EXPECT_EQ(grid.key({1 + 0.5 * cell, 2, 3}), 0u);
  // Outside the box: clamped to its cells.
  EXPECT_EQ(grid.key({-100, 2, 3}), 0u);
  EXPECT_EQ(grid.key({100, 2, 3}), kAllX);
}

TEST(MortonGrid, APointOrNoneHasOneCell) {
  EXPECT_EQ(MortonGrid::around({}).key({1, 2, 3}), 0u);
  const MortonGrid one = MortonGrid::around({{1, 2, 3}});
  EXPECT_EQ(one.cells_per_metre, 0.0);
  EXPECT_EQ(one.key({1, 2, 3}), 0u);
  EXPECT_EQ(one.key({5, 5, 5}), 0u);
}

/// Random points in a box with ids 1000 + 7 k (not their row numbers).
struct Points {
  std::vector<Vec3> position;
  std::vector<std::int64_t> id;
};
Points random_points(std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-0.5, 2.0);
  Points p;
  for (std::size_t k = 0; k < n; ++k) {
    p.position.push_back({u(rng), 0.5 * u(rng), u(rng)});
    p.id.push_back(1000 + 7 * static_cast<std::int64_t>(k));
  }
  return p;
}

/// The ids in canonical order.
std::vector<std::int64_t> canonical_ids(const Points& p) {
  std::vector<std::int64_t> ids;
  for (const std::int32_t old : canonical_particle_order(p.position, p.id))
    ids.push_back(p.id[old]);
  return ids;
}

TEST(CanonicalOrder, DoesNotDependOnTheRowOrder) {
  const Points points = random_points(2000);
  const std::vector<std::int64_t> expected = canonical_ids(points);
  std::vector<std::size_t> rows(points.id.size());
  std::iota(rows.begin(), rows.end(), 0);
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    std::shuffle(rows.begin(), rows.end(), std::mt19937_64(seed));
    Points shuffled;
    for (const std::size_t r : rows) {
      shuffled.position.push_back(points.position[r]);
      shuffled.id.push_back(points.id[r]);
    }
    EXPECT_EQ(canonical_ids(shuffled), expected) << "seed " << seed;
  }
  // And it is a spatial order: consecutive particles are close. Measured: the mean step along the
  // curve is 0.15 of the random rows' (0.21 against 1.39, about the box size).
  auto mean_step = [&](const std::vector<std::int32_t>& old_at) {
    double sum = 0.0;
    for (std::size_t k = 1; k < old_at.size(); ++k) {
      sum += norm(points.position[old_at[k]] - points.position[old_at[k - 1]]);
    }
    return sum / static_cast<double>(old_at.size() - 1);
  };
  std::vector<std::int32_t> as_given(points.id.size());
  std::iota(as_given.begin(), as_given.end(), 0);
  EXPECT_LT(mean_step(canonical_particle_order(points.position, points.id)),
            0.25 * mean_step(as_given));
}

TEST(CanonicalOrder, TiesGoById) {
  // Three coincident particles (one key) between two others, given out of id order.
  const std::vector<Vec3> x{{1, 1, 1}, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {1, 1, 1}};
  const std::vector<std::int64_t> id{5, 40, -3, 1, 2};
  const std::vector<std::int32_t> old_at = canonical_particle_order(x, id);
  std::vector<std::int64_t> ids;
  for (const std::int32_t old : old_at) ids.push_back(id[old]);
  EXPECT_EQ(ids, (std::vector<std::int64_t>{40, -3, 2, 5, 1}));
}

TEST(CanonicalOrder, BondsByTheirLowerThenHigherParticle) {
  // (3,1) (0,4) (2,0) (1,2) (4,3): by (lower, higher) (0,2) (0,4) (1,2) (1,3) (3,4).
  const std::vector<std::int32_t> alpha{3, 0, 2, 1, 4};
  const std::vector<std::int32_t> beta{1, 4, 0, 2, 3};
  EXPECT_EQ(canonical_bond_order(alpha, beta), (std::vector<std::int32_t>{2, 1, 3, 0, 4}));
  // One pair twice, either way round (a scenario refuses that): by input order.
  EXPECT_EQ(canonical_bond_order({1, 0, 2}, {2, 5, 1}), (std::vector<std::int32_t>{1, 0, 2}));
}

TEST(CanonicalOrder, InversePermutation) {
  const std::vector<std::int32_t> old_at{2, 0, 3, 1};
  EXPECT_EQ(inverse_permutation(old_at), (std::vector<std::int32_t>{1, 3, 0, 2}));
  std::vector<double> v{10, 11, 12, 13};
  permute(v, old_at);
  EXPECT_EQ(v, (std::vector<double>{12, 10, 13, 11}));
  std::vector<double> unfilled;
  permute(unfilled, old_at);
  EXPECT_TRUE(unfilled.empty());
}

TEST(StoreReorder, ParticlesCarryEveryField) {
  ParticleStore p;
  for (int k = 0; k < 3; ++k) {
    const double s = k + 1.0;
    p.add(10 * k, {s, 0, 0}, 0.1 * s, 1000.0 * s, k);
    p.velocity[k] = {0, s, 0};
    p.angular_velocity[k] = {0, 0, s};
    p.orientation[k] = {s, 0, 0, 0};
    p.force[k] = {s, s, 0};
    p.torque[k] = {0, s, s};
    p.translation_free[k] = {s, 1, 1};
    p.rotation_free[k] = {1, s, 1};
    p.position[k] = {s, 1, 0};
  }
  const ParticleStore before = p;
  const std::vector<std::int32_t> old_at{2, 0, 1};
  p.reorder(old_at);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto o = static_cast<std::size_t>(old_at[k]);
    EXPECT_EQ(p.id[k], before.id[o]);
    EXPECT_EQ(p.radius[k], before.radius[o]);
    EXPECT_EQ(p.mass[k], before.mass[o]);
    EXPECT_EQ(p.inertia[k], before.inertia[o]);
    EXPECT_EQ(p.material[k], before.material[o]);
    EXPECT_EQ(p.reference_position[k], before.reference_position[o]);
    EXPECT_EQ(p.position[k], before.position[o]);
    EXPECT_EQ(p.velocity[k], before.velocity[o]);
    EXPECT_EQ(p.angular_velocity[k], before.angular_velocity[o]);
    EXPECT_EQ(p.orientation[k].w, before.orientation[o].w);
    EXPECT_EQ(p.force[k], before.force[o]);
    EXPECT_EQ(p.torque[k], before.torque[o]);
    EXPECT_EQ(p.translation_free[k], before.translation_free[o]);
    EXPECT_EQ(p.rotation_free[k], before.rotation_free[o]);
  }
}

TEST(StoreReorder, BondsCarryTheirConstantsAndInputRow) {
  BondStore b;
  for (int k = 0; k < 3; ++k) {
    const double s = k + 1.0;
    BondConstants c;
    c.stiffness = {s, 2 * s, 3 * s, 4 * s};
    c.arm_offset = 0.01 * s;
    b.add(k, k + 1, c, 0.1 * s, 0.5 * s, k);
    b.strength[k] = {100 * s, 200 * s};
  }
  const BondStore before = b;
  const std::vector<std::int32_t> old_at{1, 2, 0};
  b.reorder(old_at);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto o = static_cast<std::size_t>(old_at[k]);
    EXPECT_EQ(b.alpha[k], before.alpha[o]);
    EXPECT_EQ(b.beta[k], before.beta[o]);
    EXPECT_EQ(b.input_row[k], static_cast<std::int32_t>(o));
    EXPECT_EQ(b.stiffness[k].k_ben, before.stiffness[o].k_ben);
    EXPECT_EQ(b.arm_offset[k], before.arm_offset[o]);
    EXPECT_EQ(b.radius[k], before.radius[o]);
    EXPECT_EQ(b.rest_length[k], before.rest_length[o]);
    EXPECT_EQ(b.material[k], before.material[o]);
    EXPECT_EQ(b.strength[k].shear, before.strength[o].shear);
  }
}

}  // namespace
}  // namespace bpm
