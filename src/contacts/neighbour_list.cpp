#include "contacts/neighbour_list.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "spatial/cell_grid.hpp"

namespace bpm {

void NeighbourList::build(const std::vector<Vec3>& position, const std::vector<double>& radius, double skin) {
  if (!(skin > 0.0)) throw InputError("contacts", "the Verlet skin must be positive");
  const std::size_t n = position.size();
  skin_ = skin;
  ++builds_;
  position_at_build_ = position;
  row_start_.assign(n + 1, 0);
  first_.clear();
  second_.clear();
  if (n == 0) return;
  // Cells of side 2 R_max + skin (spatial/cell_grid.hpp): every listed pair lies in the same or an
  // adjacent cell. At most about 2N cells, so memory stays O(N) however sparse the particles.
  const double r_max = *std::max_element(radius.begin(), radius.end());
  CellGrid grid(bounding_box(position), 2.0 * r_max + skin, 2 * n + 1);
  grid.build(position);
  const auto count = static_cast<std::int64_t>(n);

  // One pass over fixed chunks of consecutive particles: each chunk collects its rows (each row
  // sorted) into its own buffer, then the buffers are concatenated in chunk order. The chunks do
  // not depend on the thread count, so neither does the list.
  constexpr std::int64_t kChunk = 512;
  const std::int64_t chunks = (count + kChunk - 1) / kChunk;
  std::vector<std::vector<std::int32_t>> found(static_cast<std::size_t>(chunks));
#pragma omp parallel for schedule(dynamic, 1) if (count > kParallelMinItems)
  for (std::int64_t c = 0; c < chunks; ++c) {
    std::vector<std::int32_t>& out = found[c];
    for (std::int64_t i = c * kChunk; i < std::min(count, (c + 1) * kChunk); ++i) {
      const std::size_t begin = out.size();
      const Vec3 xi = position[static_cast<std::size_t>(i)];
      const double ri = radius[static_cast<std::size_t>(i)];
      grid.for_each_near(xi, [&](std::int32_t j) {
        if (j <= i) return;
        const double reach = ri + radius[static_cast<std::size_t>(j)] + skin;
        if (norm2(position[static_cast<std::size_t>(j)] - xi) < reach * reach) out.push_back(j);
      });
      std::sort(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
      row_start_[i + 1] = static_cast<std::int32_t>(out.size() - begin);
    }
  }
  for (std::size_t i = 0; i < n; ++i) row_start_[i + 1] += row_start_[i];
  first_.resize(static_cast<std::size_t>(row_start_[n]));
  second_.resize(static_cast<std::size_t>(row_start_[n]));
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
  for (std::int64_t c = 0; c < chunks; ++c) {
    std::copy(found[c].begin(), found[c].end(), second_.begin() + row_start_[c * kChunk]);
    for (std::int64_t i = c * kChunk; i < std::min(count, (c + 1) * kChunk); ++i) {
      std::fill(first_.begin() + row_start_[i], first_.begin() + row_start_[i + 1], static_cast<std::int32_t>(i));
    }
  }
}

void NeighbourList::restore(State state) {
  row_start_ = std::move(state.row_start);
  first_ = std::move(state.first);
  second_ = std::move(state.second);
  position_at_build_ = std::move(state.position_at_build);
  skin_ = state.skin;
  builds_ = state.builds;
}

bool NeighbourList::needs_rebuild(const std::vector<Vec3>& position) const {
  if (builds_ == 0 || position.size() != position_at_build_.size()) return true;
  const auto n = static_cast<std::int64_t>(position.size());
  const double limit = 0.25 * skin_ * skin_;  // (skin/2)^2
  const double moved = parallel_reduce(
      n, 0.0,
      [&](std::int64_t i) {
        return norm2(position[static_cast<std::size_t>(i)] - position_at_build_[static_cast<std::size_t>(i)]);
      },
      [](double a, double b) { return std::max(a, b); });
  return moved > limit;
}

}  // namespace bpm
