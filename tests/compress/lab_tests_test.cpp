// The laboratory strength tests (compress/uniaxial_compression.hpp): direct tension pulls a bonded
// lattice's columns apart at their bonds' strength sigma_t pi r_b^2, with the body's E in tension
// equal to the one in compression; the Brazilian test reports 2 F / (pi D t) with D and t measured
// and ends at its split.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "compress/compress_helpers.hpp"
#include "compress/uniaxial_compression.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

constexpr double kTensileStrength = 30e6;  // Pa

/// The lattice with every bond's tensile strength sigma_t (shear unbreakable).
Model breakable_lattice(int nx, int ny, int nz) {
  Model model = test::lattice(nx, ny, nz, 1e9);
  BondMaterial m;
  m.tensile_strength.value = kTensileStrength;
  model.bonds.draw_strengths({m}, 1);
  model.finalize();
  return model;
}

TEST(LabTests, DirectTensionBreaksTheColumnsAtTheirBondsStrength) {
  const int nx = 3, ny = 3, nz = 10;
  Model model = breakable_lattice(nx, ny, nz);
  UniaxialCompression s;
  s.test = LabTest::tension;
  s.strain_rate =
      0.2;  // quasi-static: a compressive wave crosses the 20 mm 150 times before the peak
  s.target_strain = 5e-5;  // the bonds break near 1.35e-4: 9 bonds of 3e-7 m stretch over 20 mm
  s.fit_from = 0.3;
  s.failure_drop = 0.5;
  s.max_strain = 3e-4;
  s.curve_points = 100;  // a point every 5e-7 of strain: the peak within 0.4 %
  const CompressionResult r = run_uniaxial_compression(model, s);
  EXPECT_EQ(r.test, LabTest::tension);
  EXPECT_EQ(r.stop, "failure");
  EXPECT_EQ(r.grip_particles,
            static_cast<std::size_t>(2 * nx * ny));  // one layer at each end (2 R_max)
  // Every column's bonds carry F / (nx ny) in pure tension: the first breaks at sigma_t pi r_b^2.
  const double peak = nx * ny * kTensileStrength * std::numbers::pi * 1e-6;
  EXPECT_NEAR(r.peak_force / peak, 1.0, 1e-2);
  EXPECT_NEAR(r.strength, r.peak_force / r.sample.area, 1e-12 * r.strength);
  EXPECT_LT(r.peak_kinetic_ratio, 1e-2) << "quasi-static at the peak";
  EXPECT_LT(r.peak_force_imbalance, 1e-2);
  const CompressionPoint& last = r.curve.back();
  EXPECT_GT(last.bonds_broken, 0u);
  EXPECT_EQ(last.bonds_broken_tension, last.bonds_broken);  // no bond fails in shear
  // Before the peak the grips pull the bonds alone: the body's E is the columns' n_x n_y k_n L / A,
  // as in compression, and a simple cubic lattice has no lateral strain.
  const double k_n = 200e9 * std::numbers::pi * 1e-6 / 2e-3;
  ASSERT_TRUE(r.body.valid);
  EXPECT_NEAR(r.body.youngs_modulus / (nx * ny * k_n * 2e-3 / r.sample.area), 1.0, 2e-3);
  EXPECT_NEAR(r.body.poissons_ratio, 0.0, 1e-3);
  // The stiffness between the grips: the nz - 1 bonds of a column in series (nothing else is).
  EXPECT_NEAR(r.stiffness / (nx * ny * k_n / (nz - 1)), 1.0, 2e-3);
}

TEST(LabTests, BrazilianReportsTwoFOverPiDt) {
  // A one-layer square lattice in the x-z plane, loaded along x: D = 16 mm, t = 2 R = 2 mm.
  Model model = breakable_lattice(8, 1, 8);
  UniaxialCompression s;
  s.test = LabTest::brazilian;
  s.axis = {1.0, 0.0, 0.0};
  s.disc_axis = {0.0, 1.0, 0.0};
  s.strain_rate = 5.0;
  s.target_strain = 1e-3;
  const CompressionResult r = run_uniaxial_compression(model, s);
  EXPECT_NEAR(r.thickness, 2e-3, 1e-15);
  EXPECT_NEAR(r.sample.length, 16e-3, 1e-15);
  EXPECT_NEAR(r.strength, 2.0 * r.peak_force / (std::numbers::pi * 16e-3 * 2e-3),
              1e-12 * r.strength);
  EXPECT_GT(r.peak_force, 0.0);
  EXPECT_FALSE(r.body.valid);  // a disc across its diameter has no uniform middle third
  s.disc_axis = {1.0, 0.0, 0.0};
  EXPECT_THROW(run_uniaxial_compression(model, s), InputError);
}

/// A test to failure ends where the force falls to failure_drop of its peak; the Brazilian test at
/// its split, 0.8 of the peak, where failure_drop is lower (the split halves carry load again).
TEST(LabTests, TheBrazilianTestEndsAtTheSplit) {
  UniaxialCompression s;
  EXPECT_EQ(failure_fraction(s), 0.0);  // to target_strain
  s.failure_drop = 0.5;
  EXPECT_EQ(failure_fraction(s), 0.5);
  s.test = LabTest::brazilian;
  EXPECT_EQ(failure_fraction(s), 0.8);
  s.failure_drop = 0.9;
  EXPECT_EQ(failure_fraction(s), 0.9);
  s.failure_drop = 0.0;
  EXPECT_EQ(failure_fraction(s), 0.0);
}

}  // namespace
}  // namespace bpm
