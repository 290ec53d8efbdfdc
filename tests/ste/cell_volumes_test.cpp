// Particle volumes: the clipped radical Voronoi cells tile the sample's convex body (measured as
// measure_sample measures it), the inner cells of a lattice are L^3, and the solid-fraction volumes
// add up to l A.
#include <gtest/gtest.h>

#include <numeric>

#include "compress/sample_geometry.hpp"
#include "ste/cell_volumes.hpp"
#include "ste_helpers.hpp"

namespace bpm {
namespace {

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(CellVolumes, LatticeCellsTileTheClippedBox) {
  const test::Lattice g{6, 5, 4, 1e-3};
  const Model model = test::lattice_model(g, 1e6, 1e5);
  const double L = g.spacing;
  for (const Vec3 axis : {Vec3{0, 0, 1}, Vec3{1, 0, 0}}) {
    for (const int planes : {4, 36}) {
      const ste::SampleHull hull = ste::sample_hull(model.particles, axis, planes);
      const std::vector<double> v = ste::voronoi_volumes(model.particles, hull);
      // The faces are among the planes here, so the prism is measure_sample's l x A.
      const SampleGeometry s = measure_sample(model.particles, axis, planes);
      EXPECT_NEAR(hull.volume(), s.length * s.area, 1e-12 * s.length * s.area);
      EXPECT_NEAR(sum(v), s.length * s.area, 1e-9 * s.length * s.area) << planes << " planes";
      // An inner particle's cell is the lattice cube.
      EXPECT_NEAR(v[static_cast<std::size_t>(g.index(2, 2, 2))], L * L * L, 1e-12 * L * L * L);
    }
  }
  // With four side planes along the lattice axes the body is the box itself, 6 x 5 x 4 cells of L^3.
  const std::vector<double> v = ste::voronoi_volumes(model.particles, ste::sample_hull(model.particles, {0, 0, 1}, 4));
  EXPECT_NEAR(sum(v), 120.0 * L * L * L, 1e-12 * 120.0 * L * L * L);
  for (const double c : v) {
    EXPECT_NEAR(c, L * L * L, 1e-12 * L * L * L);
  }
}

// Turned about the axis, the lattice's faces no longer lie along the evenly spaced directions;
// the planes from the hull's long edges keep them exact: the cross-section is the 6L x 5L
// rectangle with corners rounded by R (area 30 L^2 - (4 - pi) R^2; the 36 directions cut the
// corners to ~1e-4 of it), where measure_sample's 360 directions overestimate by ~1e-3.
TEST(CellVolumes, TurnedBoxFacesStayExact) {
  const test::Lattice g{6, 5, 4, 1e-3};
  Model model = test::lattice_model(g, 1e6, 1e5);
  const double L = g.spacing, R = 0.5 * L, t = 0.3;
  for (Vec3& x : model.particles.position) x = {std::cos(t) * x.x - std::sin(t) * x.y, std::sin(t) * x.x + std::cos(t) * x.y, x.z};
  const ste::SampleHull hull = ste::sample_hull(model.particles, {0, 0, 1}, 36);
  const double exact = 30.0 * L * L - (4.0 - 3.14159265358979323846) * R * R;
  EXPECT_NEAR(hull.area / exact, 1.0, 2e-4);
  EXPECT_NEAR(hull.top - hull.bottom, 4.0 * L, 1e-15);
  const std::vector<double> v = ste::voronoi_volumes(model.particles, hull);
  EXPECT_NEAR(sum(v), hull.volume(), 1e-9 * hull.volume());
  EXPECT_NEAR(v[static_cast<std::size_t>(g.index(2, 2, 2))], L * L * L, 1e-12 * L * L * L);
  const SampleGeometry s = measure_sample(model.particles, {0, 0, 1});
  EXPECT_GT(s.area / exact - 1.0, 2e-4);  // why the long-edge planes are there
}

TEST(CellVolumes, RadicalCellsOfAPolydispersePackingTileTheBody) {
  const Model model = test::random_packing(1500, 3);
  const ParticleStore& p = model.particles;
  const ste::SampleHull hull = ste::sample_hull(p, {0, 0, 1}, 36);
  const std::vector<double> v = ste::voronoi_volumes(p, hull);
  EXPECT_NEAR(sum(v), hull.volume(), 1e-9 * hull.volume());
  const SampleGeometry s = measure_sample(p, {0, 0, 1});
  EXPECT_NEAR(hull.volume() / (s.length * s.area), 1.0, 5e-3);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_GT(v[i], 0.0) << i;
    // A cell holds at least its sphere's share of the packing; none is absurdly large.
    EXPECT_LT(v[i], 20.0 * p.radius[i] * p.radius[i] * p.radius[i]) << i;
  }
}

TEST(CellVolumes, SolidFractionVolumesAddUpToTheSample) {
  const Model model = test::random_packing(1500, 3);
  const SampleGeometry s = measure_sample(model.particles, {0, 0, 1});
  const std::vector<double> v = ste::solid_fraction_volumes(model.particles, s.length * s.area);
  EXPECT_NEAR(sum(v), s.length * s.area, 1e-12 * s.length * s.area);
  const double phi = ste::solid_fraction(model.particles, s.length * s.area);
  EXPECT_GT(phi, 0.5);
  EXPECT_LT(phi, 0.65);
  EXPECT_NEAR(v[0] * phi, 4.0 / 3.0 * 3.14159265358979323846 * std::pow(model.particles.radius[0], 3), 1e-12 * v[0]);
}

}  // namespace
}  // namespace bpm
