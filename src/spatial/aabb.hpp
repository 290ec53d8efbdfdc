#pragma once
/// Axis-aligned bounding boxes: a container's extent (structure/container.hpp) and the region a
/// cell grid covers (spatial/cell_grid.hpp).
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

}  // namespace bpm
