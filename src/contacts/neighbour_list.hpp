#pragma once
/// Verlet list of candidate contact pairs, built with the cell grid (spatial/cell_grid.hpp) in O(N)
/// time and memory.
///
/// A pair (i, j), i < j, is listed when its surface gap |x_j - x_i| - R_i - R_j is below the skin.
/// No pair can come into contact before some particle has moved half the skin, so the list is
/// rebuilt only then (needs_rebuild). Pairs are stored sorted by (i, j) as rows per i (CSR); each
/// row is built independently and sorted, so the list is the same for any thread count.
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

class NeighbourList {
 public:
  /// Lists every pair with gap < skin (m, > 0) and remembers the positions for needs_rebuild.
  void build(const std::vector<Vec3>& position, const std::vector<double>& radius, double skin);

  /// True when the list was never built, the particle count changed, or some particle has moved
  /// more than skin/2 since the last build.
  bool needs_rebuild(const std::vector<Vec3>& position) const;

  std::size_t size() const { return second_.size(); }
  std::size_t particle_count() const { return row_start_.empty() ? 0 : row_start_.size() - 1; }
  double skin() const { return skin_; }
  std::int64_t builds() const { return builds_; }

  /// Pairs of row i are [row_start()[i], row_start()[i+1]), sorted by j; first()[k] = i.
  const std::vector<std::int32_t>& row_start() const { return row_start_; }
  const std::vector<std::int32_t>& first() const { return first_; }
  const std::vector<std::int32_t>& second() const { return second_; }

  /// Everything the list holds, for checkpoints (scenario/checkpoint.hpp): a restored list rebuilds
  /// at the same step as the original would.
  struct State {
    std::vector<std::int32_t> row_start, first, second;
    std::vector<Vec3> position_at_build;
    double skin = 0.0;
    std::int64_t builds = 0;
  };
  State state() const { return {row_start_, first_, second_, position_at_build_, skin_, builds_}; }
  void restore(State state);

 private:
  std::vector<std::int32_t> row_start_, first_, second_;
  std::vector<Vec3> position_at_build_;
  double skin_ = 0.0;
  std::int64_t builds_ = 0;
};

}  // namespace bpm
