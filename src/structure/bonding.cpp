#include "structure/bonding.hpp"

#include <algorithm>

#include "spatial/cell_grid.hpp"

namespace bpm {

std::vector<std::pair<std::int32_t, std::int32_t>> find_bond_pairs(const Packing& p, const Aabb& box,
                                                                   const BondCriterion& criterion) {
  if (p.size() < 2 || (!criterion.contact_radius_multiplier && !criterion.max_gap)) return {};
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  const double eta = criterion.contact_radius_multiplier.value_or(0.0);
  const double gap = criterion.max_gap.value_or(-1.0);
  double reach = 0.0;
  if (criterion.contact_radius_multiplier) reach = std::max(reach, eta * 2.0 * r_max);
  if (criterion.max_gap) reach = std::max(reach, 2.0 * r_max + gap);
  reach *= 1.0 + 1e-6;
  return find_pairs(p.position, box, reach, [&](std::int32_t i, std::int32_t j, double d) {
    const double sum = p.radius[static_cast<std::size_t>(i)] + p.radius[static_cast<std::size_t>(j)];
    const double tol = 1e-9 * sum;
    if (criterion.contact_radius_multiplier && d <= eta * sum + tol) return true;  // Chen §2.2
    return criterion.max_gap && d - sum <= gap + tol;
  });
}

std::vector<std::int32_t> assign_bond_materials(std::size_t count, const std::vector<double>& fractions,
                                                std::mt19937_64& rng) {
  std::vector<std::int32_t> material(count, 0);
  if (fractions.size() < 2) return material;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto& m : material) {
    const double x = u(rng);
    double cumulative = 0.0;
    std::size_t k = 0;
    for (; k + 1 < fractions.size(); ++k) {
      cumulative += fractions[k];
      if (x < cumulative) break;
    }
    m = static_cast<std::int32_t>(k);
  }
  return material;
}

}  // namespace bpm
