#include "io/neighbour_pairs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace bpm {
namespace {

using Cell = std::array<std::int64_t, 3>;

}  // namespace

std::vector<std::pair<std::int32_t, std::int32_t>> pairs_within_gap(const std::vector<Vec3>& position,
                                                                    const std::vector<double>& radius,
                                                                    double max_gap) {
  const std::size_t n = position.size();
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  if (n < 2) return pairs;

  // Any bondable pair is at most 2 R_max + max_gap (plus the tolerance) apart, so with cells a
  // little larger than that both particles lie in the same or in neighbouring cells. The margin
  // matters: with cells of exactly that size, floor(1.2 / 0.4) = 2 but floor(1.6 / 0.4) = 4 puts two
  // touching particles two cells apart.
  Vec3 lo = position[0], hi = position[0];
  for (const Vec3& x : position) {
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[d]);
      hi[d] = std::max(hi[d], x[d]);
    }
  }
  const double r_max = *std::max_element(radius.begin(), radius.end());
  // Floor on the cell size keeps the integer cell coordinates small for a sparse, huge domain.
  const double h = std::max(1.001 * (2.0 * r_max + max_gap), 1e-12 * max_abs(hi - lo));
  auto cell_of = [&](std::size_t i) {
    Cell c;
    for (int d = 0; d < 3; ++d) c[static_cast<std::size_t>(d)] = static_cast<std::int64_t>(std::floor((position[i][d] - lo[d]) / h));
    return c;
  };

  // Sort particles by cell; each cell is then a contiguous run found by binary search.
  std::vector<Cell> cell(n);
  for (std::size_t i = 0; i < n; ++i) cell[i] = cell_of(i);
  std::vector<std::int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return cell[a] < cell[b]; });
  std::vector<Cell> sorted_cells(n);
  for (std::size_t k = 0; k < n; ++k) sorted_cells[k] = cell[order[k]];

  for (std::size_t i = 0; i < n; ++i) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const Cell c{cell[i][0] + dx, cell[i][1] + dy, cell[i][2] + dz};
          const auto [first, last] = std::equal_range(sorted_cells.begin(), sorted_cells.end(), c);
          for (auto it = first; it != last; ++it) {
            const auto j = order[static_cast<std::size_t>(it - sorted_cells.begin())];
            if (static_cast<std::size_t>(j) <= i) continue;
            const double sum = radius[i] + radius[j];
            const double gap = norm(position[j] - position[i]) - sum;
            if (gap <= max_gap + 1e-9 * sum) pairs.emplace_back(static_cast<std::int32_t>(i), j);
          }
        }
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace bpm
