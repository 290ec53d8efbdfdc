#pragma once
/// A container bounded by a closed triangulated surface (e.g. from an STL file).
///
/// - Closedness is checked on construction: every edge must be shared by exactly two triangles
///   that traverse it in opposite directions (a closed, consistently oriented 2-manifold);
///   otherwise an InputError names the file and the first offending edge.
/// - Volume by the divergence theorem (sum of signed tetrahedra), independent of the orientation.
/// - Inside test by ray casting along +z with a watertight tie-break (a symbolic perturbation of
///   the query point, evaluated identically for the two triangles sharing an edge), so rays through
///   edges and vertices are counted exactly once. A 2D grid over x-y limits the triangles tested.
/// - keep_inside moves a sphere centre to distance R from the nearest surface point (inward), using
///   a 3D grid of triangles to find the triangles within R.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "structure/container.hpp"
#include "structure/stl_mesh.hpp"

namespace bpm {

class MeshContainer final : public Container {
 public:
  /// `name` (usually the STL path) is used in error messages and describe().
  MeshContainer(TriangleMesh mesh, std::string name);
  double volume() const override { return volume_; }
  Aabb bounds() const override { return bounds_; }
  bool contains(const Vec3& p) const override;
  Vec3 keep_inside(const Vec3& centre, double radius) const override;
  std::string describe() const override;

  std::size_t triangle_count() const { return mesh_.triangles.size(); }

 private:
  struct Closest {
    Vec3 point;
    double distance2 = -1.0;  ///< < 0: none found
    std::int32_t triangle = -1;
  };
  Closest closest_within(const Vec3& p, double radius) const;  ///< triangles within `radius` only
  Closest closest_any(const Vec3& p) const;                     ///< all triangles
  void consider(const Vec3& p, std::int32_t t, Closest& best) const;

  TriangleMesh mesh_;
  std::string name_;
  double volume_ = 0.0;
  Aabb bounds_;
  std::vector<Vec3> outward_normal_;  ///< unit, per triangle

  // 2D grid (x-y) for the ray cast: cell (i, j) lists the triangles whose x-y box overlaps it.
  std::array<int, 2> grid2_n_{1, 1};
  double grid2_h_[2] = {1.0, 1.0};
  std::vector<std::int32_t> grid2_start_, grid2_items_;
  // 3D grid for the distance queries.
  std::array<int, 3> grid3_n_{1, 1, 1};
  double grid3_h_ = 1.0;
  std::vector<std::int32_t> grid3_start_, grid3_items_;
};

}  // namespace bpm
