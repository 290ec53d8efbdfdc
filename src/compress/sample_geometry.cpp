#include "compress/sample_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.hpp"

namespace bpm {

SampleGeometry measure_sample(const ParticleStore& p, const Vec3& axis, int directions) {
  if (p.size() == 0) throw InputError("sample", "has no particles", "generate or load a structure first");
  const Vec3 a = axis / norm(axis);
  // An orthonormal basis (e1, e2) of the cross-section plane.
  const Vec3 helper = std::abs(a.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  const Vec3 e1 = cross(a, helper) / norm(cross(a, helper));
  const Vec3 e2 = cross(a, e1);

  SampleGeometry g;
  g.bottom = std::numeric_limits<double>::infinity();
  g.top = -g.bottom;
  const auto m = static_cast<std::size_t>(directions);
  std::vector<double> support(m, -std::numeric_limits<double>::infinity());
  std::vector<double> cos_t(m), sin_t(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(m);
    cos_t[k] = std::cos(t);
    sin_t[k] = std::sin(t);
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.position[i];
    const double r = p.radius[i], s = dot(x, a), u = dot(x, e1), v = dot(x, e2);
    g.bottom = std::min(g.bottom, s - r);
    g.top = std::max(g.top, s + r);
    for (std::size_t k = 0; k < m; ++k) support[k] = std::max(support[k], u * cos_t[k] + v * sin_t[k] + r);
  }
  g.length = g.top - g.bottom;
  // Vertices of the circumscribed polygon: intersections of consecutive support lines
  // u cos t_k + v sin t_k = h_k; then the shoelace formula.
  std::vector<double> pu(m), pv(m);
  const double det = std::sin(2.0 * std::numbers::pi / static_cast<double>(m));
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t n = (k + 1) % m;
    pu[k] = (support[k] * sin_t[n] - support[n] * sin_t[k]) / det;
    pv[k] = (support[n] * cos_t[k] - support[k] * cos_t[n]) / det;
  }
  double twice_area = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t n = (k + 1) % m;
    twice_area += pu[k] * pv[n] - pu[n] * pv[k];
  }
  g.area = 0.5 * twice_area;
  return g;
}

}  // namespace bpm
