// Random packing and force-biased relaxation: the overlap tolerance is met, the porosity target
// is met, every sphere is inside its container, the result is fixed by the seed and does not
// depend on the number of OpenMP threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "structure/container.hpp"
#include "structure/bonding.hpp"
#include "structure/generate.hpp"
#include "structure/mesh_container.hpp"
#include "structure/stl_mesh.hpp"
#include "structure_test_util.hpp"
#include "structure/packing.hpp"
#include "structure/packing_stats.hpp"

namespace bpm {
namespace {

Packing relaxed(const Container& c, const RadiusDistribution& d, const PackingTarget& target, std::uint64_t seed,
                double tol = 0.01, RelaxationReport* report = nullptr) {
  std::mt19937_64 rng(seed);
  Packing p = insert_random(c, d, target, rng);
  const RelaxationReport r = relax(p, c, {tol, 20000});
  if (report) *report = r;
  return p;
}

/// Brute force: the largest overlap / smaller radius over all pairs.
double brute_largest_overlap(const Packing& p) {
  double worst = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double delta = p.radius[i] + p.radius[j] - norm(p.position[j] - p.position[i]);
      worst = std::max(worst, delta / std::min(p.radius[i], p.radius[j]));
    }
  return worst;
}

TEST(Packing, RelaxationMeetsTheOverlapToleranceInEveryShape) {
  const BoxContainer box({0, 0, 0}, {1, 1, 1});
  const CylinderContainer cyl({0, 0, 0}, 0.6, 1.0);
  const SphereContainer sph({0, 0, 0}, 0.6);
  const auto radii = RadiusDistribution::uniform(0.03, 0.05);
  for (const Container* c : std::vector<const Container*>{&box, &cyl, &sph}) {
    SCOPED_TRACE(c->describe());
    for (const double tol : {0.05, 0.01, 0.002}) {
      RelaxationReport r;
      const Packing p = relaxed(*c, radii, {0.45, 0}, 11, tol, &r);
      EXPECT_TRUE(r.converged);
      EXPECT_LE(r.max_overlap, tol);
      EXPECT_LE(brute_largest_overlap(p), tol);
      EXPECT_NEAR(largest_overlap(p, *c), brute_largest_overlap(p), 1e-12);
    }
  }
}

TEST(Packing, AllSpheresInsideTheContainer) {
  const CylinderContainer cyl({1, 2, 3}, 0.5, 1.2);
  const SphereContainer sph({0, 0, 0}, 0.6);
  const auto radii = RadiusDistribution::normal(0.04, 0.005);
  const Packing pc = relaxed(cyl, radii, {0.45, 0}, 3);
  for (std::size_t i = 0; i < pc.size(); ++i) {
    const Vec3 x = pc.position[i];
    const double r = pc.radius[i];
    EXPECT_LE(std::hypot(x.x - 1, x.y - 2), 0.5 - r + 1e-12);
    EXPECT_GE(x.z, 3 + r - 1e-12);
    EXPECT_LE(x.z, 4.2 - r + 1e-12);
  }
  const Packing ps = relaxed(sph, radii, {0.45, 0}, 3);
  for (std::size_t i = 0; i < ps.size(); ++i) EXPECT_LE(norm(ps.position[i]), 0.6 - ps.radius[i] + 1e-12);
}

TEST(Packing, InsideAnStlCubeAndIcosphere) {
  test::TempDir dir;
  const std::string cube_path = dir.write("cube.stl", test::binary_stl(test::cube_triangles()));
  const MeshContainer cube(read_stl(cube_path), cube_path);
  RelaxationReport r;
  const Packing p = relaxed(cube, RadiusDistribution::uniform(0.03, 0.05), {0.45, 0}, 2, 0.01, &r);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(packing_stats(p, cube, 1.0).porosity, 0.45, 2e-3);
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      EXPECT_GE(p.position[i][d], p.radius[i] - 1e-9);
      EXPECT_LE(p.position[i][d], 1.0 - p.radius[i] + 1e-9);
    }
  }
  const std::string ico_path = dir.write("ico.stl", test::ascii_stl(test::icosphere_triangles(3, 0.6)));
  const MeshContainer ico(read_stl(ico_path), ico_path);
  const Packing q = relaxed(ico, RadiusDistribution::uniform(0.03, 0.05), {0.45, 0}, 2, 0.01, &r);
  EXPECT_TRUE(r.converged);
  // The facets lie within 0.5 % of the radius inside the true sphere.
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_LE(norm(q.position[i]), 0.6 - q.radius[i] + 1e-9);
}

TEST(Packing, PorosityTargetIsMet) {
  // The radii are drawn until their volume reaches (1 - porosity) V: the achieved porosity differs
  // from the target by at most half a particle volume / V plus the (tiny) overlap lenses.
  const BoxContainer box({0, 0, 0}, {1, 1, 1});
  for (const double target : {0.4, 0.5, 0.7}) {
    const Packing p = relaxed(box, RadiusDistribution::uniform(0.02, 0.04), {target, 0}, 5);
    const PackingStats s = packing_stats(p, box, 1.0);
    EXPECT_NEAR(s.porosity, target, 2e-3) << target;
    EXPECT_LE(s.max_overlap, 0.01);
  }
}

TEST(Packing, CountTargetGivesThatManyParticles) {
  const SphereContainer sph({0, 0, 0}, 1.0);
  EXPECT_EQ(relaxed(sph, RadiusDistribution::monodisperse(0.05), {0.0, 1234}, 1).size(), 1234u);
}

bool same(const Packing& a, const Packing& b) {
  return a.size() == b.size() && std::memcmp(a.position.data(), b.position.data(), a.size() * sizeof(Vec3)) == 0 &&
         a.radius == b.radius;
}

TEST(Packing, SameSeedSameResultOtherSeedOther) {
  const CylinderContainer cyl({0, 0, 0}, 0.5, 1.0);
  const auto radii = RadiusDistribution::lognormal(0.04, 0.004);
  const Packing a = relaxed(cyl, radii, {0.45, 0}, 77), b = relaxed(cyl, radii, {0.45, 0}, 77);
  const Packing c = relaxed(cyl, radii, {0.45, 0}, 78);
  EXPECT_TRUE(same(a, b));
  EXPECT_FALSE(same(a, c));
}

TEST(Packing, IdenticalForOneAndTwoThreads) {
  // Large enough that every loop runs in parallel (more than kParallelMinItems particles).
  const BoxContainer box({0, 0, 0}, {1, 1, 1});
  const PackingTarget target{0.0, 2 * kParallelMinItems};
  const auto radii = RadiusDistribution::uniform(0.018, 0.026);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const Packing one = relaxed(box, radii, target, 9);
  const auto bonds_one = find_bond_pairs(one, box.bounds(), {1.1, std::nullopt});
  const PackingStats stats_one = packing_stats(one, box, 1.1);
  omp_set_num_threads(2);
  const Packing two = relaxed(box, radii, target, 9);
  const auto bonds_two = find_bond_pairs(two, box.bounds(), {1.1, std::nullopt});
  const PackingStats stats_two = packing_stats(two, box, 1.1);
  omp_set_num_threads(saved);
  EXPECT_TRUE(same(one, two));
  EXPECT_EQ(bonds_one, bonds_two);
  EXPECT_EQ(stats_one.porosity, stats_two.porosity);
  EXPECT_EQ(stats_one.coordination_number, stats_two.coordination_number);
  EXPECT_LE(brute_largest_overlap(one), 0.01);
}

TEST(Packing, TooFewIterationsIsReported) {
  const BoxContainer box({0, 0, 0}, {1, 1, 1});
  std::mt19937_64 rng(1);
  Packing p = insert_random(box, RadiusDistribution::monodisperse(0.04), {0.4, 0}, rng);
  const RelaxationReport r = relax(p, box, {0.01, 3});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_GT(r.max_overlap, 0.01);
}

TEST(Packing, NotRelaxedIsAnErrorNamingThePackingSectionOrAWarning) {
  GenerateSpec spec;
  spec.container = std::make_shared<BoxContainer>(Vec3{0, 0, 0}, Vec3{1, 1, 1});
  spec.radii = RadiusDistribution::monodisperse(0.04);
  spec.target.porosity = 0.4;
  spec.relaxation = {0.01, 3};
  spec.relaxation_where = "spec.yaml:7: packing";
  try {
    generate_structure(spec);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("spec.yaml:7: packing"), std::string::npos) << msg;
    EXPECT_NE(msg.find("max_iterations"), std::string::npos) << msg;
  }
  spec.fail_if_not_relaxed = false;
  EXPECT_FALSE(generate_structure(spec).relaxation.converged);
}

TEST(PackingStats, PorosityCountsOverlapLensesAndCoordination) {
  // Two unit spheres 1.5 apart in a big box: one lens of height 0.5.
  const BoxContainer box({-10, -10, -10}, {10, 10, 10});
  Packing p;
  p.position = {{0, 0, 0}, {1.5, 0, 0}, {5, 0, 0}};
  p.radius = {1.0, 1.0, 1.0};
  const double lens = std::numbers::pi * 0.25 * (2.25 + 6.0) / 18.0;  // pi h^2 (d^2 + 4 d R) / (12 d)
  const PackingStats s = packing_stats(p, box, 1.2);
  EXPECT_NEAR(s.solid_volume, 3 * 4.0 / 3.0 * std::numbers::pi - lens, 1e-12);
  EXPECT_NEAR(s.porosity, 1.0 - s.solid_volume / 8000.0, 1e-15);
  EXPECT_DOUBLE_EQ(s.coordination_number, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.max_overlap, 0.5);
}

}  // namespace
}  // namespace bpm
