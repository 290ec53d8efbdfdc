#include "dsm/platen_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace bpm {
namespace {

/// Index of the coordinate axis that `axis` is (x, y or z, either sign).
int coordinate_axis(const Vec3& axis) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(std::abs(axis[k]) - 1.0) < 1e-12) return k;
  }
  throw InputError(
      "compression.axis", "the direct stiffness method needs the loading axis along x, y or z",
      "rotate the structure so that the load is along a coordinate axis, e.g. axis: [0, 0, 1]");
}

/// Root of each particle's cluster of intact bonds (union-find).
std::vector<std::int32_t> bond_clusters(const Model& model) {
  std::vector<std::int32_t> parent(model.particles.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::int32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const BondStore& b = model.bonds;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b.intact[i]) continue;
    const auto ra = root(b.alpha[i]), rb = root(b.beta[i]);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = root(static_cast<std::int32_t>(i));
  return parent;
}

}  // namespace

DofConstraints platen_constraints(const Model& model, const PlatenLoading& load, int dofs,
                                  bool kinematic) {
  const ParticleStore& p = model.particles;
  DofConstraints c;
  c.dofs = dofs;
  c.axial_dof = coordinate_axis(load.axis);
  c.fixed.assign(static_cast<std::size_t>(dofs) * p.size(), 0);
  c.value.assign(c.fixed.size(), 0.0);
  auto fix = [&](std::int32_t particle, int k, double v) {
    const auto dof = static_cast<std::size_t>(dofs) * static_cast<std::size_t>(particle) +
                     static_cast<std::size_t>(k);
    c.fixed[dof] = 1;
    c.value[dof] = v;
  };

  // The scenario's own fixed DOFs (boundary_conditions: fix) stay fixed.
  bool scenario_holds_translation = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (p.translation_free[i][k] == 0.0) {
        fix(static_cast<std::int32_t>(i), k, 0.0);
        scenario_holds_translation = true;
      }
      if (dofs == 6 && p.rotation_free[i][k] == 0.0) fix(static_cast<std::int32_t>(i), 3 + k, 0.0);
    }
  }
  // The largest bonded cluster carries the load; the rest is held.
  const auto cluster = bond_clusters(model);
  std::vector<std::int32_t> count(p.size(), 0);
  for (const auto r : cluster) ++count[r];
  const auto main =
      static_cast<std::int32_t>(std::max_element(count.begin(), count.end()) - count.begin());
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (cluster[i] == main) continue;
    ++c.detached_particles;
    for (int k = 0; k < dofs; ++k) fix(static_cast<std::int32_t>(i), k, 0.0);
  }
  std::vector<std::int32_t> bottom, top;
  for (const auto i : load.bottom)
    if (cluster[i] == main) bottom.push_back(i);
  for (const auto i : load.top)
    if (cluster[i] == main) top.push_back(i);
  if (bottom.empty() || top.empty()) {
    throw InputError("sample", "its largest bonded cluster does not reach both platens",
                     "check the structure: the bonds must connect the sample from bottom to top");
  }

  const int ax = c.axial_dof, lat1 = (ax + 1) % 3, lat2 = (ax + 2) % 3;
  if (kinematic) {
    const double top_value =
        -load.displacement * load.axis[ax];  // the upper platen moves along -axis
    for (const auto i : bottom) fix(i, ax, 0.0);
    for (const auto i : top) fix(i, ax, top_value);
    if (!load.frictionless) {
      for (const auto i : bottom) {
        fix(i, lat1, 0.0);
        fix(i, lat2, 0.0);
      }
      for (const auto i : top) {
        fix(i, lat1, 0.0);
        fix(i, lat2, 0.0);
      }
      return c;
    }
  }
  // Pins against lateral sliding and spin about the axis (see the header), unless the scenario
  // holds particles itself: then its constraints decide, and pins could add load paths.
  if (scenario_holds_translation || !load.frictionless) return c;  // frictional platens hold them
  double mean1 = 0.0, mean2 = 0.0;
  for (const auto i : bottom) {
    mean1 += p.position[i][lat1] / static_cast<double>(bottom.size());
    mean2 += p.position[i][lat2] / static_cast<double>(bottom.size());
  }
  auto lateral_distance2 = [&](std::int32_t i, double x1, double x2) {
    const double d1 = p.position[i][lat1] - x1, d2 = p.position[i][lat2] - x2;
    return d1 * d1 + d2 * d2;
  };
  const auto centre = *std::min_element(bottom.begin(), bottom.end(), [&](auto a, auto b) {
    return lateral_distance2(a, mean1, mean2) < lateral_distance2(b, mean1, mean2);
  });
  fix(centre, lat1, 0.0);
  fix(centre, lat2, 0.0);
  // The second pin may come from either set (a one-particle bottom, e.g. a sphere's pole).
  std::vector<std::int32_t> candidates = bottom;
  candidates.insert(candidates.end(), top.begin(), top.end());
  const double c1 = p.position[centre][lat1], c2 = p.position[centre][lat2];
  const auto far = *std::max_element(candidates.begin(), candidates.end(), [&](auto a, auto b) {
    return lateral_distance2(a, c1, c2) < lateral_distance2(b, c1, c2);
  });
  if (lateral_distance2(far, c1, c2) <= 0.0) {
    throw InputError("sample",
                     "the platen contacts lie on one line along the axis, so spin about it is free",
                     "use a platen with friction or a sample with a flat end");
  }
  // Spin moves `far` across its lateral offset (d1, d2), i.e. along (-d2, d1): hold the larger
  // part.
  const double d1 = p.position[far][lat1] - c1, d2 = p.position[far][lat2] - c2;
  fix(far, std::abs(d2) >= std::abs(d1) ? lat1 : lat2, 0.0);
  c.pinned = true;
  return c;
}

}  // namespace bpm
