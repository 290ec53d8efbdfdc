#include "structure/packing_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "spatial/cell_grid.hpp"

namespace bpm {
namespace {

/// Volume of the lens shared by spheres R1, R2 at centre distance d (0 if apart; the smaller sphere
/// if one holds the other).
double lens_volume(double r1, double r2, double d) {
  if (d >= r1 + r2) return 0.0;
  if (d <= std::abs(r1 - r2)) {
    const double r = std::min(r1, r2);
    return 4.0 / 3.0 * std::numbers::pi * r * r * r;
  }
  const double h = r1 + r2 - d;
  return std::numbers::pi * h * h * (d * d + 2.0 * d * (r1 + r2) - 3.0 * (r1 - r2) * (r1 - r2)) / (12.0 * d);
}

}  // namespace

PackingStats packing_stats(const Packing& p, const Container& container, double eta) {
  PackingStats s;
  s.particles = p.size();
  s.container_volume = container.volume();
  s.contact_radius_multiplier = eta;
  if (p.size() == 0) {
    s.porosity = 1.0;
    return s;
  }
  s.min_radius = *std::min_element(p.radius.begin(), p.radius.end());
  s.max_radius = *std::max_element(p.radius.begin(), p.radius.end());
  double sum_r = 0.0, solid = 0.0;
  for (const double r : p.radius) {
    sum_r += r;
    solid += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  }
  s.mean_radius = sum_r / static_cast<double>(p.size());

  const auto reach = std::max(eta, 1.0) * 2.0 * s.max_radius * (1.0 + 1e-6);
  const auto near = find_pairs(p.position, container.bounds(), reach, [&](std::int32_t i, std::int32_t j, double d) {
    return d <= eta * (p.radius[static_cast<std::size_t>(i)] + p.radius[static_cast<std::size_t>(j)]) ||
           d < p.radius[static_cast<std::size_t>(i)] + p.radius[static_cast<std::size_t>(j)];
  });
  std::size_t contacts = 0;
  for (const auto& [i, j] : near) {  // in sorted order, so the sums are reproducible
    const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
    const double d = norm(p.position[sj] - p.position[si]), sum = p.radius[si] + p.radius[sj];
    if (d <= eta * sum) ++contacts;
    if (d < sum) {
      solid -= lens_volume(p.radius[si], p.radius[sj], d);
      s.max_overlap = std::max(s.max_overlap, (sum - d) / std::min(p.radius[si], p.radius[sj]));
    }
  }
  s.solid_volume = solid;
  s.porosity = 1.0 - solid / s.container_volume;
  s.coordination_number = 2.0 * static_cast<double>(contacts) / static_cast<double>(p.size());
  return s;
}

}  // namespace bpm
