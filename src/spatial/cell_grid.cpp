#include "spatial/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace bpm {

CellGrid::CellGrid(const Aabb& box, double min_cell, std::size_t max_cells) : origin_(box.min) {
  const Vec3 size = box.size();
  h_ = std::max(min_cell, 1e-12 * max_abs(size));
  // Grow the cells until the grid has at most max_cells (a sparse packing in a huge box).
  for (;;) {
    double cells = 1.0;
    for (int d = 0; d < 3; ++d) {
      n_[static_cast<std::size_t>(d)] = std::max(1, static_cast<int>(std::ceil(size[d] / h_)));
      cells *= n_[static_cast<std::size_t>(d)];
    }
    if (cells <= static_cast<double>(std::max<std::size_t>(max_cells, 1))) break;
    h_ *= 1.25;
  }
  start_.assign(static_cast<std::size_t>(n_[0]) * static_cast<std::size_t>(n_[1]) *
                        static_cast<std::size_t>(n_[2]) +
                    1,
                0);
}

std::array<int, 3> CellGrid::cell_of(const Vec3& p) const {
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d) {
    const double x = std::floor((p[d] - origin_[d]) / h_);
    c[static_cast<std::size_t>(d)] = static_cast<int>(
        std::clamp(x, 0.0, static_cast<double>(n_[static_cast<std::size_t>(d)] - 1)));
  }
  return c;
}

std::size_t CellGrid::index_of(const Vec3& p) const {
  const auto c = cell_of(p);
  return (static_cast<std::size_t>(c[0]) * static_cast<std::size_t>(n_[1]) +
          static_cast<std::size_t>(c[1])) *
             static_cast<std::size_t>(n_[2]) +
         static_cast<std::size_t>(c[2]);
}

void CellGrid::build(const std::vector<Vec3>& position) {
  const std::size_t cells = start_.size() - 1;
  std::fill(start_.begin(), start_.end(), 0);
  cell_.resize(position.size());
  for (std::size_t i = 0; i < position.size(); ++i) {
    cell_[i] = static_cast<std::int32_t>(index_of(position[i]));
    ++start_[static_cast<std::size_t>(cell_[i]) + 1];
  }
  for (std::size_t k = 0; k < cells; ++k) start_[k + 1] += start_[k];
  items_.resize(position.size());
  std::vector<std::int32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < position.size(); ++i) {
    items_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_[i])]++)] =
        static_cast<std::int32_t>(i);
  }
}

}  // namespace bpm
