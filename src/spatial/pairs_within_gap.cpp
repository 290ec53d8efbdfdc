#include "spatial/pairs_within_gap.hpp"

#include <algorithm>

#include "spatial/cell_grid.hpp"

namespace bpm {

std::vector<std::pair<std::int32_t, std::int32_t>> pairs_within_gap(
    const std::vector<Vec3>& position, const std::vector<double>& radius, double max_gap) {
  if (position.size() < 2) return {};
  const double r_max = *std::max_element(radius.begin(), radius.end());
  // Every accepted pair is closer than 2 R_max (1 + 1e-9) + max_gap: the search reach, with room.
  const double reach = (2.0 * r_max + max_gap) * (1.0 + 1e-6);
  return find_pairs(position, bounding_box(position), reach,
                    [&](std::int32_t i, std::int32_t j, double distance) {
                      const double sum =
                          radius[static_cast<std::size_t>(i)] + radius[static_cast<std::size_t>(j)];
                      return distance - sum <= max_gap + 1e-9 * sum;
                    });
}

}  // namespace bpm
