#pragma once
// Template body of find_pairs (cell_grid.hpp).
#include <algorithm>

#include "core/parallel.hpp"

namespace bpm {

template <class Accept>
std::vector<std::pair<std::int32_t, std::int32_t>> find_pairs(const std::vector<Vec3>& position,
                                                              const Aabb& box, double reach,
                                                              Accept&& accept) {
  using Pair = std::pair<std::int32_t, std::int32_t>;
  const auto n = static_cast<std::int64_t>(position.size());
  CellGrid grid(box, reach, 2 * position.size() + 1);
  grid.build(position);
  std::vector<Pair> pairs;
#pragma omp parallel if (n >= kParallelMinItems)
  {
    std::vector<Pair> local;
#pragma omp for schedule(static) nowait
    for (std::int64_t i = 0; i < n; ++i) {
      const Vec3 xi = position[static_cast<std::size_t>(i)];
      grid.for_each_near(xi, [&](std::int32_t j) {
        if (j <= i) return;
        const double d = norm(position[static_cast<std::size_t>(j)] - xi);
        if (d < reach && accept(static_cast<std::int32_t>(i), j, d))
          local.emplace_back(static_cast<std::int32_t>(i), j);
      });
    }
#pragma omp critical(bpm_find_pairs)
    pairs.insert(pairs.end(), local.begin(), local.end());
  }
  std::sort(pairs.begin(), pairs.end());  // thread order is arbitrary; sorting makes it canonical
  return pairs;
}

}  // namespace bpm
