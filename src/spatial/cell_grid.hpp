#pragma once
/// The one neighbour search of bpmkit (the contacts' Verlet list, automatic bonds, the packing and
/// its bonding, the STE's local map): a uniform cell grid over a fixed box (O(N) to build, O(1)
/// candidates per particle for a bounded radius ratio). Particles are binned by counting sort, so
/// each cell lists its particles in increasing index order: the candidate order, and so every
/// result built from it, is the same for any thread count.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/vec3.hpp"
#include "spatial/aabb.hpp"

namespace bpm {

class CellGrid {
 public:
  /// A grid over `box` with cells of at least `min_cell` (m) on a side, with at most about
  /// `max_cells` cells (cells grow for a sparse domain). Points outside the box go to the nearest
  /// border cell, so they are still found (only less efficiently).
  CellGrid(const Aabb& box, double min_cell, std::size_t max_cells);

  /// Bins the points; call again after they move.
  void build(const std::vector<Vec3>& position);

  /// Calls visit(j) for every point j in the 27 cells around `p` (including the point itself).
  template <class Visit>
  void for_each_near(const Vec3& p, Visit&& visit) const {
    const std::array<int, 3> c = cell_of(p);
    for (int i = std::max(c[0] - 1, 0); i <= std::min(c[0] + 1, n_[0] - 1); ++i) {
      for (int j = std::max(c[1] - 1, 0); j <= std::min(c[1] + 1, n_[1] - 1); ++j) {
        const std::size_t row = (static_cast<std::size_t>(i) * static_cast<std::size_t>(n_[1]) +
                                 static_cast<std::size_t>(j)) *
                                static_cast<std::size_t>(n_[2]);
        const std::size_t k0 = row + static_cast<std::size_t>(std::max(c[2] - 1, 0));
        const std::size_t k1 = row + static_cast<std::size_t>(std::min(c[2] + 1, n_[2] - 1));
        // Cells k0..k1 are adjacent in memory, so their lists form one run.
        for (auto m = start_[k0]; m < start_[k1 + 1]; ++m)
          visit(items_[static_cast<std::size_t>(m)]);
      }
    }
  }

  double cell_size() const { return h_; }

 private:
  std::array<int, 3> cell_of(const Vec3& p) const;
  std::size_t index_of(const Vec3& p) const;

  Vec3 origin_;
  double h_ = 1.0;
  std::array<int, 3> n_{1, 1, 1};
  std::vector<std::int32_t> start_, items_, cell_;
};

/// All pairs (i < j), sorted, for which accept(i, j, distance) holds, among pairs closer than
/// `reach` (m). Parallel (OpenMP); the result does not depend on the thread count.
template <class Accept>
std::vector<std::pair<std::int32_t, std::int32_t>> find_pairs(const std::vector<Vec3>& position,
                                                              const Aabb& box, double reach,
                                                              Accept&& accept);

}  // namespace bpm

#include "spatial/cell_grid_impl.hpp"
