// The local stiffness map (Jarolin 4.4, Eq. 36) and its VTK file.
#include <gtest/gtest.h>

#include <string>

#include "common/test_files.hpp"
#include "ste/ste_vtk.hpp"
#include "ste/stiffness_tensor_estimation.hpp"
#include "ste_helpers.hpp"

namespace bpm {
namespace {

using ste::SteOptions;
using ste::SteResult;

SteOptions with_map() {
  SteOptions o;
  o.volumes = ste::VolumeMethod::voronoi;
  o.local_map = true;
  return o;
}

// Inside a uniform lattice the local sphere (diameter 3 d: the particle and its 18 nearest
// neighbours) holds only exact particles, so E_local = k_n / L there; the boundary is softer, so
// the centre lies above the mean and a corner below (excess = (local - mean) / mean).
TEST(LocalMap, UniformLatticeIsExactInsideAndSofterAtTheBoundary) {
  const test::Lattice g{9, 9, 9, 1e-3};
  const double k_n = 1e6;
  const SteResult r = ste::estimate_stiffness(test::lattice_model(g, k_n, 3e5), with_map());
  ASSERT_TRUE(r.local);
  const ste::LocalMap& m = *r.local;
  EXPECT_EQ(m.valid_count, r.particles);
  EXPECT_NEAR(m.sphere_diameter, 3e-3, 1e-15);
  const auto centre = static_cast<std::size_t>(g.index(4, 4, 4));
  const auto corner = static_cast<std::size_t>(g.index(0, 0, 0));
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(m.modulus[centre][d], k_n / g.spacing, 1e-9 * k_n / g.spacing);
    EXPECT_GT(m.excess[centre][d], 0.0);
    EXPECT_LT(m.excess[corner][d], 0.0);
    EXPECT_NEAR(m.excess[centre][d], (m.modulus[centre][d] - m.mean[d]) / m.mean[d], 1e-15);
  }
  // The mean is the arithmetic mean of the local values (Eq. 36).
  double sum = 0.0;
  for (const Vec3& e : m.modulus) sum += e.x;
  EXPECT_NEAR(m.mean.x, sum / static_cast<double>(m.modulus.size()), 1e-12 * m.mean.x);
}

// Two stacked blocks (bonds k and 4k): the map shows the stiff half four times as stiff.
TEST(LocalMap, ShowsAStiffnessGradient) {
  const test::Lattice g{8, 8, 16, 1e-3};
  const Model model = test::lattice_model(g, [](int, int, int k, int) {
    const double f = k < 8 ? 1.0 : 4.0;
    return BondStiffness{f * 1e6, f * 3e5, 1e-3, 1e-3};
  });
  const SteResult r = ste::estimate_stiffness(model, with_map());
  const Vec3 soft = r.local->modulus[static_cast<std::size_t>(g.index(4, 4, 3))];
  const Vec3 stiff = r.local->modulus[static_cast<std::size_t>(g.index(4, 4, 12))];
  EXPECT_NEAR(stiff.z / soft.z, 4.0, 1e-9);
  EXPECT_LT(r.local->excess[static_cast<std::size_t>(g.index(4, 4, 3))].z, 0.0);
  EXPECT_GT(r.local->excess[static_cast<std::size_t>(g.index(4, 4, 12))].z, 0.0);
}

TEST(SteVtk, WritesEveryParticleWithItsFields) {
  const test::Lattice g{4, 4, 4, 1e-3};
  const Model model = test::lattice_model(g, 1e6, 3e5);
  const SteResult r = ste::estimate_stiffness(model, with_map());
  test::TempDir dir;
  const std::string path = dir.path("sub/ste.vtp");
  ste::write_ste_vtp(path, model.particles, r);
  const std::string text = test::read_text(path);
  EXPECT_NE(text.find("NumberOfPoints=\"64\""), std::string::npos);
  for (const char* field : {"\"radius\"", "\"id\"", "\"volume\"", "\"used\"", "\"coordination\"", "\"C11\"", "\"C66\"", "\"C23\"",
                            "\"E_local_x\"", "\"E_local_z\"", "\"E_excess_x\"", "\"E_excess_z\""}) {
    EXPECT_NE(text.find(std::string("Name=") + field), std::string::npos) << field;
  }
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos);
  // Without the map the local fields are left out.
  const std::string plain = ste::ste_polydata_vtp(model.particles, ste::estimate_stiffness(model));
  EXPECT_EQ(plain.find("E_local_x"), std::string::npos);
}

}  // namespace
}  // namespace bpm
