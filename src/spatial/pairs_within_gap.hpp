#pragma once
/// Finds the particle pairs close enough to bond (`bonds: auto` in a scenario), with the cell grid
/// (spatial/cell_grid.hpp).
#include <cstdint>
#include <utility>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

/// All pairs (i < j), sorted, whose surface gap |x_j - x_i| - R_i - R_j is at most max_gap. A
/// relative tolerance of 1e-9 (R_i + R_j) is added so that particles meant to touch, whose gap is
/// zero only up to round-off in their coordinates, are found with max_gap = 0.
std::vector<std::pair<std::int32_t, std::int32_t>> pairs_within_gap(
    const std::vector<Vec3>& position, const std::vector<double>& radius, double max_gap);

}  // namespace bpm
