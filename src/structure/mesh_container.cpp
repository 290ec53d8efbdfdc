#include "structure/mesh_container.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/error.hpp"

namespace bpm {
namespace {

/// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, §5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

/// Sign (+1/-1) of the x-y edge function of the directed edge u->v at the point (px, py) perturbed
/// to (px + e, py + e^2) (simulation of simplicity). The value is computed for the edge in a
/// canonical vertex order, so the two triangles sharing an edge get exactly opposite signs: a ray
/// through an edge or a vertex is then counted in exactly one triangle.
int edge_sign(const Vec3& u, std::int32_t iu, const Vec3& v, std::int32_t iv, double px, double py) {
  const bool swapped = iu > iv;
  const Vec3& a = swapped ? v : u;
  const Vec3& b = swapped ? u : v;
  const double e = (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
  int s = 0;
  if (e != 0.0) s = e > 0.0 ? 1 : -1;
  else if (b.y != a.y) s = b.y > a.y ? -1 : 1;  // d e / d px = -(b.y - a.y)
  else s = b.x > a.x ? 1 : -1;                   // d e / d py = b.x - a.x
  return swapped ? -s : s;
}

/// Compressed lists: items of bin k are items[start[k] .. start[k+1]). `bins_of(t, visit)` calls
/// visit(bin) for every bin of item t.
template <class BinsOf>
void build_bins(std::size_t items, std::size_t bins, const BinsOf& bins_of, std::vector<std::int32_t>& start,
                std::vector<std::int32_t>& list) {
  start.assign(bins + 1, 0);
  for (std::size_t t = 0; t < items; ++t) bins_of(t, [&](std::size_t k) { ++start[k + 1]; });
  for (std::size_t k = 0; k < bins; ++k) start[k + 1] += start[k];
  list.resize(static_cast<std::size_t>(start[bins]));
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < items; ++t) {
    bins_of(t, [&](std::size_t k) { list[static_cast<std::size_t>(fill[k]++)] = static_cast<std::int32_t>(t); });
  }
}

}  // namespace

MeshContainer::MeshContainer(TriangleMesh mesh, std::string name) : mesh_(std::move(mesh)), name_(std::move(name)) {
  const auto& V = mesh_.vertices;
  const auto& T = mesh_.triangles;
  auto at = [&](std::int32_t i) -> const Vec3& { return V[static_cast<std::size_t>(i)]; };

  // Closed and consistently oriented: each undirected edge is traversed once in each direction.
  std::map<std::pair<std::int32_t, std::int32_t>, std::array<int, 2>> edges;
  for (const auto& t : T) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      ++edges[{std::min(a, b), std::max(a, b)}][a < b ? 0 : 1];
    }
  }
  std::size_t open = 0, non_manifold = 0, flipped = 0;
  std::string first_problem;
  for (const auto& [e, count] : edges) {
    std::string problem;
    if (count[0] + count[1] == 1) problem = fmt::format("open edge ({} triangle)", 1), ++open;
    else if (count[0] + count[1] > 2) problem = fmt::format("edge shared by {} triangles", count[0] + count[1]), ++non_manifold;
    else if (count[0] != 1) problem = "edge traversed twice in the same direction (inconsistent orientation)", ++flipped;
    if (!problem.empty() && first_problem.empty()) {
      const Vec3 &a = at(e.first), &b = at(e.second);
      first_problem = fmt::format("{} between ({:.6g}, {:.6g}, {:.6g}) and ({:.6g}, {:.6g}, {:.6g})", problem, a.x, a.y,
                                  a.z, b.x, b.y, b.z);
    }
  }
  if (open + non_manifold + flipped > 0) {
    throw InputError(name_,
                     fmt::format("the surface is not a closed, consistently oriented triangle mesh: {} open edges, {} "
                                 "edges shared by more than two triangles, {} inconsistently oriented edges; first: {}",
                                 open, non_manifold, flipped, first_problem),
                     "close the holes and fix the normals (e.g. in MeshLab or Blender's 3D-Print toolbox) and export again");
  }

  // Volume (divergence theorem) and orientation.
  double six_v = 0.0;
  for (const auto& t : T) six_v += dot(at(t[0]), cross(at(t[1]), at(t[2])));
  volume_ = std::abs(six_v) / 6.0;
  if (!(volume_ > 0.0)) throw InputError(name_, "the surface encloses no volume", "give a closed solid");
  const double outward = six_v > 0.0 ? 1.0 : -1.0;
  outward_normal_.resize(T.size());
  for (std::size_t i = 0; i < T.size(); ++i) {
    const Vec3 n = cross(at(T[i][1]) - at(T[i][0]), at(T[i][2]) - at(T[i][0]));
    const double len = norm(n);
    outward_normal_[i] = len > 0.0 ? (outward / len) * n : Vec3{};
  }

  bounds_ = {V[0], V[0]};
  for (const Vec3& v : V) {
    for (int d = 0; d < 3; ++d) {
      bounds_.min[d] = std::min(bounds_.min[d], v[d]);
      bounds_.max[d] = std::max(bounds_.max[d], v[d]);
    }
  }
  const Vec3 size = bounds_.size();
  auto tri_box = [&](std::size_t t) {
    Aabb b{at(T[t][0]), at(T[t][0])};
    for (int k = 1; k < 3; ++k) {
      const Vec3& v = at(T[t][static_cast<std::size_t>(k)]);
      for (int d = 0; d < 3; ++d) {
        b.min[d] = std::min(b.min[d], v[d]);
        b.max[d] = std::max(b.max[d], v[d]);
      }
    }
    return b;
  };

  // 2D grid: about one triangle per cell on a side of sqrt(T), at most 512 x 512.
  const int side2 = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(T.size()))), 1, 512);
  for (int d = 0; d < 2; ++d) {
    grid2_n_[static_cast<std::size_t>(d)] = side2;
    grid2_h_[d] = std::max(size[d], 1e-300) / side2;
  }
  auto cell2 = [&](double x, int d) {
    return std::clamp(static_cast<int>(std::floor((x - bounds_.min[d]) / grid2_h_[d])), 0, grid2_n_[static_cast<std::size_t>(d)] - 1);
  };
  build_bins(
      T.size(), static_cast<std::size_t>(grid2_n_[0]) * static_cast<std::size_t>(grid2_n_[1]),
      [&](std::size_t t, auto&& visit) {
        const Aabb b = tri_box(t);
        for (int i = cell2(b.min.x, 0); i <= cell2(b.max.x, 0); ++i)
          for (int j = cell2(b.min.y, 1); j <= cell2(b.max.y, 1); ++j)
            visit(static_cast<std::size_t>(i) * static_cast<std::size_t>(grid2_n_[1]) + static_cast<std::size_t>(j));
      },
      grid2_start_, grid2_items_);

  // 3D grid: cubic cells, at most 64 along the longest side.
  grid3_h_ = std::max(max_abs(size), 1e-300) / 64.0;
  for (int d = 0; d < 3; ++d) {
    grid3_n_[static_cast<std::size_t>(d)] = std::clamp(static_cast<int>(std::ceil(size[d] / grid3_h_)), 1, 64);
  }
  auto cells3 = [&](const Aabb& b, auto&& visit) {
    std::array<int, 3> lo{}, hi{};
    for (int d = 0; d < 3; ++d) {
      const int n = grid3_n_[static_cast<std::size_t>(d)];
      lo[static_cast<std::size_t>(d)] = std::clamp(static_cast<int>(std::floor((b.min[d] - bounds_.min[d]) / grid3_h_)), 0, n - 1);
      hi[static_cast<std::size_t>(d)] = std::clamp(static_cast<int>(std::floor((b.max[d] - bounds_.min[d]) / grid3_h_)), 0, n - 1);
    }
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int k = lo[2]; k <= hi[2]; ++k)
          visit((static_cast<std::size_t>(i) * static_cast<std::size_t>(grid3_n_[1]) + static_cast<std::size_t>(j)) *
                    static_cast<std::size_t>(grid3_n_[2]) +
                static_cast<std::size_t>(k));
  };
  build_bins(
      T.size(), static_cast<std::size_t>(grid3_n_[0]) * static_cast<std::size_t>(grid3_n_[1]) * static_cast<std::size_t>(grid3_n_[2]),
      [&](std::size_t t, auto&& visit) { cells3(tri_box(t), visit); }, grid3_start_, grid3_items_);
}

bool MeshContainer::contains(const Vec3& p) const {
  if (p.x < bounds_.min.x || p.x > bounds_.max.x || p.y < bounds_.min.y || p.y > bounds_.max.y ||
      p.z < bounds_.min.z || p.z > bounds_.max.z) {
    return false;
  }
  const auto ci = std::clamp(static_cast<int>(std::floor((p.x - bounds_.min.x) / grid2_h_[0])), 0, grid2_n_[0] - 1);
  const auto cj = std::clamp(static_cast<int>(std::floor((p.y - bounds_.min.y) / grid2_h_[1])), 0, grid2_n_[1] - 1);
  const std::size_t cell = static_cast<std::size_t>(ci) * static_cast<std::size_t>(grid2_n_[1]) + static_cast<std::size_t>(cj);
  int crossings = 0;
  for (auto k = grid2_start_[cell]; k < grid2_start_[cell + 1]; ++k) {
    const auto& t = mesh_.triangles[static_cast<std::size_t>(grid2_items_[static_cast<std::size_t>(k)])];
    const Vec3& a = mesh_.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh_.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh_.vertices[static_cast<std::size_t>(t[2])];
    // A triangle seen edge-on from the ray (zero projected area) never holds the perturbed point.
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0.0) continue;
    const int s0 = edge_sign(a, t[0], b, t[1], p.x, p.y);
    const int s1 = edge_sign(b, t[1], c, t[2], p.x, p.y);
    const int s2 = edge_sign(c, t[2], a, t[0], p.x, p.y);
    if (s0 != s1 || s1 != s2) continue;
    // Height of the triangle above (p.x, p.y), from the barycentric weights.
    const double wa = (b.x - p.x) * (c.y - p.y) - (b.y - p.y) * (c.x - p.x);
    const double wb = (c.x - p.x) * (a.y - p.y) - (c.y - p.y) * (a.x - p.x);
    const double wc = (a.x - p.x) * (b.y - p.y) - (a.y - p.y) * (b.x - p.x);
    const double z = (wa * a.z + wb * b.z + wc * c.z) / (wa + wb + wc);
    if (z >= p.z) ++crossings;
  }
  return crossings % 2 == 1;
}

void MeshContainer::consider(const Vec3& p, std::int32_t t, Closest& best) const {
  const auto& tri = mesh_.triangles[static_cast<std::size_t>(t)];
  const Vec3 q = closest_on_triangle(p, mesh_.vertices[static_cast<std::size_t>(tri[0])],
                                     mesh_.vertices[static_cast<std::size_t>(tri[1])],
                                     mesh_.vertices[static_cast<std::size_t>(tri[2])]);
  const double d2 = norm2(q - p);
  if (best.distance2 < 0.0 || d2 < best.distance2) best = {q, d2, t};
}

MeshContainer::Closest MeshContainer::closest_within(const Vec3& p, double radius) const {
  Closest best;
  std::array<int, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    const int n = grid3_n_[static_cast<std::size_t>(d)];
    const double a = std::floor((p[d] - radius - bounds_.min[d]) / grid3_h_);
    const double b = std::floor((p[d] + radius - bounds_.min[d]) / grid3_h_);
    if (b < 0.0 || a > n - 1) return best;  // the sphere misses the grid: no triangle near
    lo[static_cast<std::size_t>(d)] = static_cast<int>(std::max(a, 0.0));
    hi[static_cast<std::size_t>(d)] = static_cast<int>(std::min(b, static_cast<double>(n - 1)));
  }
  for (int i = lo[0]; i <= hi[0]; ++i) {
    for (int j = lo[1]; j <= hi[1]; ++j) {
      for (int k = lo[2]; k <= hi[2]; ++k) {
        const std::size_t cell = (static_cast<std::size_t>(i) * static_cast<std::size_t>(grid3_n_[1]) + static_cast<std::size_t>(j)) *
                                     static_cast<std::size_t>(grid3_n_[2]) +
                                 static_cast<std::size_t>(k);
        for (auto m = grid3_start_[cell]; m < grid3_start_[cell + 1]; ++m) consider(p, grid3_items_[static_cast<std::size_t>(m)], best);
      }
    }
  }
  if (best.distance2 > radius * radius) best.distance2 = -1.0;
  return best;
}

MeshContainer::Closest MeshContainer::closest_any(const Vec3& p) const {
  Closest best;
  for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) consider(p, static_cast<std::int32_t>(t), best);
  return best;
}

Vec3 MeshContainer::keep_inside(const Vec3& centre, double radius) const {
  Vec3 c = centre;
  // Each pass resolves the nearest wall; a few passes settle corners, where up to three walls are
  // within R (the relaxation repeats this every iteration anyway).
  for (int pass = 0; pass < 8; ++pass) {
    const bool inside = contains(c);
    Closest near = closest_within(c, radius);
    if (inside && near.distance2 < 0.0) return c;
    if (!inside && near.distance2 < 0.0) near = closest_any(c);
    const double d = std::sqrt(near.distance2);
    const Vec3 inward = -outward_normal_[static_cast<std::size_t>(near.triangle)];
    if (d > 0.0) {
      const Vec3 away = (inside ? 1.0 / d : -1.0 / d) * (c - near.point);  // unit, into the solid
      c = near.point + radius * away;
    } else {
      c = near.point + radius * inward;
    }
  }
  return c;
}

std::string MeshContainer::describe() const {
  return fmt::format("closed surface {} ({} triangles, volume {:.6g} m^3)", name_, mesh_.triangles.size(), volume_);
}

}  // namespace bpm
