// Bonding: the cell-grid pair search equals a brute-force O(N^2) search for the contact-radius
// criterion (Chen 2022 §2.2), the gap criterion and both; bond materials follow the mixing ratio
// within binomial tolerance (Jarolin case 2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "structure/bonding.hpp"
#include "structure/container.hpp"
#include "structure/packing.hpp"

namespace bpm {
namespace {

using Pairs = std::vector<std::pair<std::int32_t, std::int32_t>>;

Pairs brute_force(const Packing& p, const BondCriterion& c) {
  Pairs out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double d = norm(p.position[j] - p.position[i]), sum = p.radius[i] + p.radius[j];
      const bool by_eta = c.contact_radius_multiplier && d <= *c.contact_radius_multiplier * sum + 1e-9 * sum;
      const bool by_gap = c.max_gap && d - sum <= *c.max_gap + 1e-9 * sum;
      if (by_eta || by_gap) out.emplace_back(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
    }
  return out;
}

TEST(Bonding, EqualsBruteForce) {
  const CylinderContainer cyl({0, 0, 0}, 0.5, 1.0);
  std::mt19937_64 rng(4);
  Packing p = insert_random(cyl, RadiusDistribution::uniform(0.02, 0.045), {0.42, 0}, rng);
  relax(p, cyl, {0.01, 20000});
  ASSERT_GT(p.size(), 1000u);
  for (const BondCriterion c : {BondCriterion{1.0, std::nullopt}, BondCriterion{1.15, std::nullopt},
                                BondCriterion{std::nullopt, 0.0}, BondCriterion{std::nullopt, 0.01},
                                BondCriterion{1.1, 0.008}}) {
    const Pairs fast = find_bond_pairs(p, cyl.bounds(), c);
    EXPECT_EQ(fast, brute_force(p, c));
    if (c.contact_radius_multiplier.value_or(0) > 1.05) {
      EXPECT_GT(fast.size(), 2 * p.size());
    }
  }
  EXPECT_TRUE(find_bond_pairs(p, cyl.bounds(), {}).empty());
}

TEST(Bonding, MixingRatioWithinBinomialTolerance) {
  for (const double f : {0.1, 0.4, 0.9}) {
    std::mt19937_64 rng(12);
    const std::size_t n = 30000;
    const auto mat = assign_bond_materials(n, {f, 1.0 - f}, rng);
    const auto first = static_cast<double>(std::count(mat.begin(), mat.end(), 0));
    EXPECT_NEAR(first, f * n, 4.0 * std::sqrt(n * f * (1 - f))) << f;  // 4 sigma
    EXPECT_EQ(std::count(mat.begin(), mat.end(), 0) + std::count(mat.begin(), mat.end(), 1), static_cast<long>(n));
  }
  std::mt19937_64 rng(1);
  const auto three = assign_bond_materials(60000, {0.2, 0.3, 0.5}, rng);
  for (int k = 0; k < 3; ++k) {
    const double p = std::vector<double>{0.2, 0.3, 0.5}[static_cast<std::size_t>(k)];
    EXPECT_NEAR(static_cast<double>(std::count(three.begin(), three.end(), k)), p * 60000, 4.0 * std::sqrt(60000 * p * (1 - p)));
  }
  std::mt19937_64 rng_a(5), rng_b(5);
  EXPECT_EQ(assign_bond_materials(100, {0.5, 0.5}, rng_a), assign_bond_materials(100, {0.5, 0.5}, rng_b));
  EXPECT_EQ(assign_bond_materials(100, {1.0}, rng_a), std::vector<std::int32_t>(100, 0));
}

}  // namespace
}  // namespace bpm
