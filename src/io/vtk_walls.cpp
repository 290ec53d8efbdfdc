#include "io/vtk_walls.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "spatial/aabb.hpp"

namespace bpm {
namespace {

/// The particles' bounding box, radii included; a 1 m cube about the origin without particles.
Aabb particle_box(const ParticleStore& p) {
  if (p.size() == 0) return {{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}};
  return sphere_bounding_box(p.position, p.radius);
}

/// A unit vector normal to the unit vector n.
Vec3 normal_to(const Vec3& n) {
  const Vec3 least = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
                         ? Vec3{1, 0, 0}
                     : std::abs(n.y) <= std::abs(n.z) ? Vec3{0, 1, 0}
                                                      : Vec3{0, 0, 1};
  const Vec3 e = cross(n, least);
  return e * (1.0 / norm(e));
}

class Mesh {
 public:
  /// Adds a polygon through `corners` for wall w.
  void polygon(const std::vector<Vec3>& corners, std::int32_t w) {
    std::vector<std::int64_t> ids;
    for (const Vec3& c : corners) {
      ids.push_back(static_cast<std::int64_t>(points.size()));
      points.push_back(c);
    }
    polygons.push_back(std::move(ids));
    wall.push_back(w);
  }
  /// The point on the circle of radius r about c in the plane of unit vectors e1, e2.
  static Vec3 on_circle(const Vec3& c, const Vec3& e1, const Vec3& e2, double r, int k) {
    const double a = 2.0 * std::numbers::pi * k / kVtkWallSegments;
    return c + r * std::cos(a) * e1 + r * std::sin(a) * e2;
  }

  std::vector<Vec3> points;
  std::vector<std::vector<std::int64_t>> polygons;
  std::vector<std::int32_t> wall;
};

void draw(Mesh& m, const Wall& w, std::int32_t index, const Aabb& box) {
  switch (w.shape) {
    case WallShape::plane: {
      const Vec3 e1 = normal_to(w.normal), e2 = cross(w.normal, e1);
      const Vec3 centre = 0.5 * (box.min + box.max);
      const Vec3 c = centre - dot(centre - w.point, w.normal) * w.normal;
      const double h = 0.6 * norm(box.size());
      m.polygon(
          {c - h * e1 - h * e2, c + h * e1 - h * e2, c + h * e1 + h * e2, c - h * e1 + h * e2},
          index);
      return;
    }
    case WallShape::rectangle: {
      const Vec3 e1 = w.half_width * w.edge, e2 = w.half_height * cross(w.normal, w.edge);
      m.polygon({w.point - e1 - e2, w.point + e1 - e2, w.point + e1 + e2, w.point - e1 + e2},
                index);
      return;
    }
    case WallShape::disc: {
      const Vec3 e1 = normal_to(w.normal), e2 = cross(w.normal, e1);
      std::vector<Vec3> rim;
      for (int k = 0; k < kVtkWallSegments; ++k)
        rim.push_back(Mesh::on_circle(w.point, e1, e2, w.radius, k));
      m.polygon(rim, index);
      return;
    }
    case WallShape::cylinder: {
      // The axial extent of the box's corners: the particles lie within it.
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int c = 0; c < 8; ++c) {
        const Vec3 corner{c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y,
                          c & 4 ? box.max.z : box.min.z};
        const double s = dot(corner - w.point, w.normal);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
      const double margin = 0.05 * (hi - lo);
      const Vec3 bottom = w.point + (lo - margin) * w.normal,
                 top = w.point + (hi + margin) * w.normal;
      const Vec3 e1 = normal_to(w.normal), e2 = cross(w.normal, e1);
      for (int k = 0; k < kVtkWallSegments; ++k) {
        const int next = (k + 1) % kVtkWallSegments;
        m.polygon({Mesh::on_circle(bottom, e1, e2, w.radius, k),
                   Mesh::on_circle(bottom, e1, e2, w.radius, next),
                   Mesh::on_circle(top, e1, e2, w.radius, next),
                   Mesh::on_circle(top, e1, e2, w.radius, k)},
                  index);
      }
      return;
    }
  }
}

}  // namespace

VtkPolyData walls_polydata(const std::vector<Wall>& walls, const ParticleStore& particles) {
  const Aabb box = particle_box(particles);
  Mesh m;
  for (std::size_t w = 0; w < walls.size(); ++w)
    draw(m, walls[w], static_cast<std::int32_t>(w), box);
  VtkPolyData d(m.points);
  for (const auto& polygon : m.polygons) d.polygon(polygon);
  std::vector<Vec3> force, displacement, velocity;
  std::vector<std::string> names;
  for (const std::int32_t w : m.wall) {
    const Wall& wall = walls[static_cast<std::size_t>(w)];
    force.push_back(wall.force);
    displacement.push_back(wall.displacement);
    velocity.push_back(wall.velocity);
  }
  for (const Wall& w : walls) names.push_back(w.name);
  VtkArrays& cells = d.cell_data();
  cells.set_active("wall", "force");
  cells.int32s("wall", m.wall);
  cells.vectors("force", force);
  cells.vectors("displacement", displacement);
  cells.vectors("velocity", velocity);
  d.field_data().strings("wall_names", names);
  return d;
}

std::string walls_vtp(const std::vector<Wall>& walls, const ParticleStore& particles,
                      VtkEncoding encoding) {
  return walls_polydata(walls, particles).vtp(encoding);
}

}  // namespace bpm
