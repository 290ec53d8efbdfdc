#pragma once
/// Axis-aligned bounding boxes: a container's extent (structure/container.hpp), the region a
/// cell grid covers (spatial/cell_grid.hpp), the spheres' extent (Voronoi container, wall drawing).
#include <algorithm>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

struct Aabb {
  Vec3 min, max;
  Vec3 size() const { return max - min; }
};

/// The smallest box holding every point (a zero box at the origin for none).
inline Aabb bounding_box(const std::vector<Vec3>& points) {
  if (points.empty()) return {};
  Aabb box{points[0], points[0]};
  for (const Vec3& p : points) {
    box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
    box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
  }
  return box;
}

/// The smallest box holding every sphere (centres[i], radii[i]); a zero box at the origin for none.
inline Aabb sphere_bounding_box(const std::vector<Vec3>& centres,
                                const std::vector<double>& radii) {
  if (centres.empty()) return {};
  Aabb box{centres[0], centres[0]};
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vec3 r{radii[i], radii[i], radii[i]};
    const Vec3 lo = centres[i] - r, hi = centres[i] + r;
    box.min = {std::min(box.min.x, lo.x), std::min(box.min.y, lo.y), std::min(box.min.z, lo.z)};
    box.max = {std::max(box.max.x, hi.x), std::max(box.max.y, hi.y), std::max(box.max.z, hi.z)};
  }
  return box;
}

}  // namespace bpm
