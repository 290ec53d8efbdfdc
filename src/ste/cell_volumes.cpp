#include "ste/cell_volumes.hpp"

#include <voro++.hh>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "spatial/aabb.hpp"

namespace bpm::ste {

namespace {

struct Point2 {
  double u, v;
  double r = 0.0;  ///< radius of the disc centred here
};

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
}

/// Convex hull (counter-clockwise, no collinear points) by Andrew's monotone chain.
std::vector<Point2> convex_hull(std::vector<Point2> p) {
  std::sort(p.begin(), p.end(), [](const Point2& a, const Point2& b) { return a.u < b.u || (a.u == b.u && a.v < b.v); });
  if (p.size() < 3) return p;
  std::vector<Point2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross2(h[k - 2], h[k - 1], p[i - 1]) <= 0.0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

/// Area of the polygon {p : p . (c_k, s_k) <= h_k for all k} (Sutherland-Hodgman from a box that
/// holds it; the half-planes are tangent to a bounded set, so the result is bounded).
double half_plane_area(const std::vector<double>& c, const std::vector<double>& s, const std::vector<double>& h) {
  double big = 0.0;
  for (const double x : h) big = std::max(big, 4.0 * std::abs(x));
  std::vector<Point2> poly = {{-big, -big}, {big, -big}, {big, big}, {-big, big}}, next;
  for (std::size_t k = 0; k < h.size() && !poly.empty(); ++k) {
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point2& a = poly[i];
      const Point2& b = poly[(i + 1) % poly.size()];
      const double da = a.u * c[k] + a.v * s[k] - h[k], db = b.u * c[k] + b.v * s[k] - h[k];
      if (da <= 0.0) next.push_back(a);
      if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
        const double t = da / (da - db);
        next.push_back({a.u + t * (b.u - a.u), a.v + t * (b.v - a.v)});
      }
    }
    poly.swap(next);
  }
  double twice = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point2& a = poly[i];
    const Point2& b = poly[(i + 1) % poly.size()];
    twice += a.u * b.v - b.u * a.v;
  }
  return 0.5 * twice;
}

}  // namespace

SampleHull sample_hull(const ParticleStore& p, const Vec3& axis, int side_planes, int face_planes) {
  if (side_planes < 3) throw InputError("stiffness tensor estimation", "needs at least 3 side planes", "hull_planes >= 3");
  if (p.size() == 0) throw InputError("stiffness tensor estimation", "the sample has no particles");
  SampleHull h;
  h.axis = axis / norm(axis);
  // The cross-section basis and angles of measure_sample (compress/sample_geometry.cpp).
  const Vec3 a = h.axis;
  const Vec3 helper = std::abs(a.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  h.e1 = cross(a, helper) / norm(cross(a, helper));
  h.e2 = cross(a, h.e1);
  const auto m = static_cast<std::size_t>(side_planes);
  std::vector<double> cos_t(m), sin_t(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(m);
    cos_t[k] = std::cos(t);
    sin_t[k] = std::sin(t);
  }
  std::vector<Point2> centre(p.size());
  h.bottom = std::numeric_limits<double>::infinity();
  h.top = -h.bottom;
  double r_max = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.position[i];
    const double s = dot(x, a);
    h.bottom = std::min(h.bottom, s - p.radius[i]);
    h.top = std::max(h.top, s + p.radius[i]);
    r_max = std::max(r_max, p.radius[i]);
    centre[i] = {dot(x, h.e1), dot(x, h.e2), p.radius[i]};
  }
  // Flat faces: the outer tangents of consecutive discs on the hull of the centres (for discs of
  // radii r0, r1 a distance L apart the tangent is turned by asin((r0 - r1) / L) from the centres'
  // edge; a face of touching particles of different radii is found exactly only so), edges longer
  // than the largest diameter, longest first, skipping directions already taken.
  constexpr double kSameAngle = 1e-6;  // rad; a direction a little off a face leaves a sliver of first order
  const std::vector<Point2> hull = convex_hull(centre);
  std::vector<std::pair<double, std::size_t>> edges;
  for (std::size_t k = 0; hull.size() >= 3 && k < hull.size(); ++k) {
    const Point2& q0 = hull[k];
    const Point2& q1 = hull[(k + 1) % hull.size()];
    const double length = std::hypot(q1.u - q0.u, q1.v - q0.v);
    if (length >= 2.0 * r_max) edges.emplace_back(length, k);
  }
  std::stable_sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  int added = 0;
  for (const auto& [length, k] : edges) {
    if (added >= face_planes) break;
    const Point2& q0 = hull[k];
    const Point2& q1 = hull[(k + 1) % hull.size()];
    // Unit edge direction t and outward normal m (counter-clockwise hull: m = (t_v, -t_u)).
    const double tu = (q1.u - q0.u) / length, tv = (q1.v - q0.v) / length;
    const double sin_phi = std::clamp((q0.r - q1.r) / length, -1.0, 1.0), cos_phi = std::sqrt(1.0 - sin_phi * sin_phi);
    const double c = cos_phi * tv + sin_phi * tu, sn = -cos_phi * tu + sin_phi * tv;
    bool close = false;
    for (std::size_t j = 0; j < cos_t.size() && !close; ++j) close = c * cos_t[j] + sn * sin_t[j] > std::cos(kSameAngle);
    if (close) continue;
    cos_t.push_back(c);
    sin_t.push_back(sn);
    ++added;
  }
  std::vector<double> support(cos_t.size(), -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t k = 0; k < cos_t.size(); ++k) {
      support[k] = std::max(support[k], centre[i].u * cos_t[k] + centre[i].v * sin_t[k] + p.radius[i]);
    }
  }
  h.area = half_plane_area(cos_t, sin_t, support);
  h.normal.push_back(-a);
  h.offset.push_back(-h.bottom);
  h.normal.push_back(a);
  h.offset.push_back(h.top);
  for (std::size_t k = 0; k < cos_t.size(); ++k) {
    h.normal.push_back(cos_t[k] * h.e1 + sin_t[k] * h.e2);
    h.offset.push_back(support[k]);
  }
  return h;
}

namespace {

/// The hull planes as one voro++ wall, in container units. A plane is applied to a cell only when
/// the particle is within `reach` of it, unless `force` is set: most cells lie deep inside and
/// voro++ would otherwise start each of them from the whole container cut by every plane. A cell
/// computed without some plane is exact if it does not reach that plane, i.e. if its largest
/// vertex distance is below `reach` (checked by the caller, which recomputes with force).
class ClipPlanes final : public voro::wall {
 public:
  ClipPlanes(std::vector<Vec3> normal, std::vector<double> offset, double reach)
      : normal_(std::move(normal)), offset_(std::move(offset)), reach_(reach) {}

  bool force = false;

  bool point_inside(double x, double y, double z) override {
    for (std::size_t k = 0; k < normal_.size(); ++k) {
      if (normal_[k].x * x + normal_[k].y * y + normal_[k].z * z > offset_[k]) return false;
    }
    return true;
  }
  bool cut_cell(voro::voronoicell& c, double x, double y, double z) override { return cut(c, x, y, z); }
  bool cut_cell(voro::voronoicell_neighbor& c, double x, double y, double z) override { return cut(c, x, y, z); }

 private:
  template <class Cell>
  bool cut(Cell& c, double x, double y, double z) {
    for (std::size_t k = 0; k < normal_.size(); ++k) {
      const Vec3& u = normal_[k];
      const double d = offset_[k] - (u.x * x + u.y * y + u.z * z);
      if (!force && d >= reach_) continue;
      if (!c.nplane(u.x, u.y, u.z, 2.0 * d, -7 - static_cast<int>(k))) return false;  // as voro::wall_plane
    }
    return true;
  }

  std::vector<Vec3> normal_;
  std::vector<double> offset_;
  double reach_;
};

}  // namespace

std::vector<double> voronoi_volumes(const ParticleStore& p, const SampleHull& hull, WorkShare share) {
  const std::size_t n = p.size();
  std::vector<double> volume(n, 0.0);
  if (n == 0) return volume;
  // Container box: the bounding box of the spheres, a second bound of the body besides the planes.
  const Aabb spheres = sphere_bounding_box(p.position, p.radius);
  const Vec3 lo = spheres.min, hi = spheres.max;
  double mean_radius = 0.0, max_radius = 0.0;
  for (const double r : p.radius) {
    mean_radius += r;
    max_radius = std::max(max_radius, r);
  }
  mean_radius /= static_cast<double>(n);
  // voro++'s tolerances are absolute (1e-11, config.hh), made for coordinates of order one: work in
  // units of the mean diameter from the box corner, x' = (x - lo) / unit.
  const double unit = 2.0 * mean_radius, cube = unit * unit * unit;
  const Vec3 size = (hi - lo) / unit;
  // About 3 particles per computational block (measured: 3-4 is fastest here, 6 takes 8 % longer).
  constexpr double kPerBlock = 3.0;
  const double block = std::cbrt(size.x * size.y * size.z * kPerBlock / static_cast<double>(n));
  int blocks[3];
  for (int d = 0; d < 3; ++d) blocks[d] = std::clamp(static_cast<int>(std::lround(size[d] / block)), 1, 4096);
  std::vector<double> offset(hull.offset.size());
  for (std::size_t k = 0; k < offset.size(); ++k) offset[k] = (hull.offset[k] - dot(hull.normal[k], lo)) / unit;
  const double reach = 4.0 * max_radius / unit;  // two largest diameters

  // voro++ keeps per-computation state in the container (radius_poly), so a container cannot be
  // shared between threads: each thread fills its own identical container (same particles, same
  // order, same walls) and computes the cells of the blocks it takes. A cell is therefore
  // computed from the same data whichever thread does it: the volumes do not depend on the thread
  // count.
  const auto n_blocks = static_cast<std::int64_t>(blocks[0]) * blocks[1] * blocks[2];
  const std::int64_t first_block = n_blocks * share.part / share.parts;
  const std::int64_t last_block = n_blocks * (share.part + 1) / share.parts;
#pragma omp parallel if (n >= static_cast<std::size_t>(kParallelMinItems))
  {
    voro::container_poly container(0.0, size.x, 0.0, size.y, 0.0, size.z, blocks[0], blocks[1], blocks[2], false,
                                   false, false, 8);
    ClipPlanes walls(hull.normal, offset, reach);
    container.add_wall(walls);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 x = (p.position[i] - lo) / unit;
      container.put(static_cast<int>(i), x.x, x.y, x.z, p.radius[i] / unit);
    }
    voro::voronoicell cell;
#pragma omp for schedule(dynamic, 16)
    for (std::int64_t b = first_block; b < last_block; ++b) {
      const auto ijk = static_cast<int>(b);
      for (int q = 0; q < container.co[ijk]; ++q) {
        walls.force = false;
        double v = 0.0;
        if (container.compute_cell(cell, ijk, q)) {
          // max_radius_squared() is (2 r)^2 (voro++ stores doubled vertex coordinates).
          if (0.5 * std::sqrt(cell.max_radius_squared()) >= reach) {
            walls.force = true;
            v = container.compute_cell(cell, ijk, q) ? cell.volume() : 0.0;
          } else {
            v = cell.volume();
          }
        }
        volume[static_cast<std::size_t>(container.id[ijk][q])] = cube * v;
      }
    }
  }
  return volume;
}

double solid_fraction(const ParticleStore& p, double sample_volume) {
  double solid = 0.0;
  for (const double r : p.radius) solid += r * r * r;
  return (4.0 / 3.0) * std::numbers::pi * solid / sample_volume;
}

std::vector<double> solid_fraction_volumes(const ParticleStore& p, double sample_volume) {
  const double phi = solid_fraction(p, sample_volume);
  std::vector<double> volume(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    volume[i] = (4.0 / 3.0) * std::numbers::pi * p.radius[i] * p.radius[i] * p.radius[i] / phi;
  }
  return volume;
}

}  // namespace bpm::ste
