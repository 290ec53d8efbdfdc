// Container shapes: volumes, inside tests and the wall constraint (keep_inside) for the analytic
// shapes, and the STL surface container checked against analytic shapes (a cube and an icosphere
// written by the test as ASCII and binary STL), including rays through edges and vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "structure/container.hpp"
#include "structure/mesh_container.hpp"
#include "structure/stl_mesh.hpp"
#include "structure_test_util.hpp"

namespace bpm {
namespace {

using test::TempDir;

TEST(Container, AnalyticVolumes) {
  EXPECT_DOUBLE_EQ(BoxContainer({0, 0, 0}, {1, 2, 3}).volume(), 6.0);
  EXPECT_DOUBLE_EQ(CylinderContainer({0, 0, 0}, 2.0, 3.0).volume(), std::numbers::pi * 12.0);
  EXPECT_DOUBLE_EQ(SphereContainer({1, 1, 1}, 2.0).volume(), 4.0 / 3.0 * std::numbers::pi * 8.0);
}

TEST(Container, KeepInsidePutsTheWholeSphereInside) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const BoxContainer box({-1, -1, -1}, {1, 2, 1});
  const CylinderContainer cyl({0, 0, -1}, 1.5, 2.0);
  const SphereContainer sph({0, 0, 0}, 1.5);
  const double r = 0.2;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Vec3 b = box.keep_inside(p, r);
    EXPECT_TRUE(b.x >= -1 + r - 1e-12 && b.x <= 1 - r + 1e-12 && b.y >= -1 + r - 1e-12 && b.y <= 2 - r + 1e-12 &&
                b.z >= -1 + r - 1e-12 && b.z <= 1 - r + 1e-12);
    const Vec3 c = cyl.keep_inside(p, r);
    EXPECT_LE(std::hypot(c.x, c.y), 1.5 - r + 1e-12);
    EXPECT_TRUE(c.z >= -1 + r - 1e-12 && c.z <= 1 - r + 1e-12);
    const Vec3 s = sph.keep_inside(p, r);
    EXPECT_LE(norm(s), 1.5 - r + 1e-12);
    // A centre that is already admissible stays where it is (up to round-off on the boundary).
    EXPECT_LT(norm(sph.keep_inside(s, r) - s), 1e-15);
    EXPECT_EQ(sph.keep_inside(0.1 * p, r), 0.1 * p);
    EXPECT_EQ(box.contains(p), std::abs(p.x) <= 1 && p.y >= -1 && p.y <= 2 && std::abs(p.z) <= 1);
  }
}

TEST(StlContainer, CubeMatchesTheBoxIncludingRaysThroughEdgesAndVertices) {
  TempDir dir;
  for (const bool binary : {false, true}) {
    const auto tris = test::cube_triangles();
    const std::string path = dir.write(binary ? "cube_bin.stl" : "cube.stl", binary ? test::binary_stl(tris) : test::ascii_stl(tris));
    const MeshContainer mesh(read_stl(path), path);
    EXPECT_EQ(mesh.triangle_count(), 12u);
    EXPECT_NEAR(mesh.volume(), 1.0, 1e-12);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-0.5, 1.5);
    for (int k = 0; k < 5000; ++k) {
      const Vec3 p{u(rng), u(rng), u(rng)};
      const bool inside = p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1 && p.z > 0 && p.z < 1;
      EXPECT_EQ(mesh.contains(p), inside) << p.x << " " << p.y << " " << p.z;
    }
    // Above x = y the vertical ray runs through the diagonal edges of the top and bottom faces.
    for (const double t : {0.1, 0.25, 0.5, 0.9}) {
      EXPECT_TRUE(mesh.contains({t, t, 0.5}));
      EXPECT_FALSE(mesh.contains({t, t, 1.5}));
      EXPECT_FALSE(mesh.contains({t, t, -0.5}));
    }
    // keep_inside: the sphere ends inside with its surface on the nearest wall.
    const double r = 0.1;
    for (int k = 0; k < 500; ++k) {
      const Vec3 c = mesh.keep_inside({u(rng), u(rng), u(rng)}, r);
      for (int d = 0; d < 3; ++d) {
        EXPECT_GE(c[d], r - 1e-9);
        EXPECT_LE(c[d], 1 - r + 1e-9);
      }
    }
  }
}

TEST(StlContainer, IcosphereMatchesTheSphere) {
  TempDir dir;
  const double radius = 2.0;
  const std::string path = dir.write("ico.stl", test::ascii_stl(test::icosphere_triangles(3, radius)));
  const MeshContainer mesh(read_stl(path), path);
  EXPECT_EQ(mesh.triangle_count(), 20u * 64u);
  EXPECT_NEAR(mesh.volume() / (4.0 / 3.0 * std::numbers::pi * radius * radius * radius), 1.0, 0.02);
  // Level-3 icosphere: every face is within 0.5 % of the radius from the true sphere.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const double d = norm(p);
    if (std::abs(d - radius) < 0.01 * radius) continue;  // between the mesh and the true sphere
    EXPECT_EQ(mesh.contains(p), d < radius) << p.x << " " << p.y << " " << p.z;
    ++checked;
  }
  EXPECT_GT(checked, 15000);
  // Through a vertex: the top of the icosahedron is not a vertex, but (0, 0, z) crosses faces'
  // shared edges on several levels; check the axis and the vertex directions.
  for (const double z : {-1.9, -1.0, 0.0, 1.0, 1.9}) EXPECT_TRUE(mesh.contains({0, 0, z}));
  EXPECT_FALSE(mesh.contains({0, 0, 2.1}));
}

TEST(StlContainer, OpenSurfaceIsRefusedNamingTheFile) {
  TempDir dir;
  auto tris = test::cube_triangles();
  tris.pop_back();
  const std::string path = dir.write("open.stl", test::ascii_stl(tris));
  const std::string msg = test::error_of([&] { MeshContainer(read_stl(path), path); });
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("open edges"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not a closed"), std::string::npos) << msg;
}

TEST(StlContainer, FlippedTriangleIsRefused) {
  TempDir dir;
  auto tris = test::cube_triangles();
  std::swap(tris[3][1], tris[3][2]);
  const std::string path = dir.write("flipped.stl", test::ascii_stl(tris));
  const std::string msg = test::error_of([&] { MeshContainer(read_stl(path), path); });
  EXPECT_NE(msg.find("inconsistently oriented"), std::string::npos) << msg;
}

TEST(StlContainer, UnreadableFilesAreRefusedNamingTheFile) {
  TempDir dir;
  const std::string missing = dir.path("missing.stl");
  EXPECT_NE(test::error_of([&] { read_stl(missing); }).find(missing), std::string::npos);
  const std::string garbage = dir.write("garbage.stl", "hello");
  const std::string msg = test::error_of([&] { read_stl(garbage); });
  EXPECT_NE(msg.find(garbage), std::string::npos) << msg;
  // Truncated binary: declares 12 triangles, holds 2.
  std::string bin = test::binary_stl(test::cube_triangles());
  bin.resize(84 + 100);
  const std::string truncated = dir.write("truncated.stl", bin);
  EXPECT_NE(test::error_of([&] { read_stl(truncated); }).find("truncated"), std::string::npos);
  const std::string bad_vertex = dir.write("bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 a\n");
  const std::string msg2 = test::error_of([&] { read_stl(bad_vertex); });
  EXPECT_NE(msg2.find(bad_vertex + ":4"), std::string::npos) << msg2;
}

TEST(StlContainer, ScaleConvertsUnits) {
  TempDir dir;
  const std::string path = dir.write("cube_mm.stl", test::ascii_stl(test::cube_triangles()));
  const MeshContainer mesh(read_stl(path, 1e-3), path);
  EXPECT_NEAR(mesh.volume(), 1e-9, 1e-21);
}

}  // namespace
}  // namespace bpm
