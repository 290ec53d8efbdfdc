// The virtual strain gauges (compress/strain_gauge.hpp): a uniform strain is measured exactly, a
// small rigid rotation gives zero to first order, only the middle third counts, and a gauge
// without a volume of particles says so.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "compress/sample_geometry.hpp"
#include "compress/strain_gauge.hpp"

namespace bpm {
namespace {

std::vector<Vec3> random_box(int n, double seed_shift = 0.0) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> x;
  for (int i = 0; i < n; ++i) x.push_back({u(rng) + seed_shift, u(rng), 3.0 * u(rng)});
  return x;
}

SampleGeometry along_z(double bottom, double top) {
  return {bottom, top, top - bottom, 1.0};
}

TEST(StrainGauge, MeasuresAUniformStrainExactly) {
  const std::vector<Vec3> x = random_box(400);
  const StrainGauge gauge(x, {0, 0, 1}, along_z(0.0, 3.0));
  ASSERT_TRUE(gauge.valid());
  // u = eps X + c with a shear part: axial -1e-3, lateral +2e-4 and +3e-4 (mean 2.5e-4).
  const GaugeStrain g = gauge.measure([&](std::int32_t p) {
    const Vec3& X = x[static_cast<std::size_t>(p)];
    return Vec3{2e-4 * X[0] + 1e-4 * X[2] + 5.0, 3e-4 * X[1], -1e-3 * X[2] + 1e-4 * X[0]};
  });
  EXPECT_NEAR(g.axial, -1e-3, 1e-15);
  EXPECT_NEAR(g.lateral, 2.5e-4, 1e-15);
}

TEST(StrainGauge, ARigidRotationIsNoStrain) {
  const std::vector<Vec3> x = random_box(400);
  const StrainGauge gauge(x, {0, 0, 1}, along_z(0.0, 3.0));
  const double angle = 1e-6;  // about y: u = angle * (z, 0, -x) to first order
  const GaugeStrain g = gauge.measure([&](std::int32_t p) {
    const Vec3& X = x[static_cast<std::size_t>(p)];
    return Vec3{angle * X[2], 0.0, -angle * X[0]};
  });
  EXPECT_NEAR(g.axial, 0.0, 1e-20);
  EXPECT_NEAR(g.lateral, 0.0, 1e-20);
}

TEST(StrainGauge, OnlyTheMiddleThirdCounts) {
  // Strain -1e-3 in the middle third, ten times that at the ends (the platen contacts' side).
  const std::vector<Vec3> x = random_box(600);
  const StrainGauge gauge(x, {0, 0, 1}, along_z(0.0, 3.0));
  std::size_t middle = 0;
  for (const Vec3& X : x) middle += X[2] >= 1.0 && X[2] <= 2.0;
  EXPECT_EQ(gauge.size(), middle);
  const GaugeStrain g = gauge.measure([&](std::int32_t p) {
    const double z = x[static_cast<std::size_t>(p)][2];
    const double w = z < 1.0   ? -1e-2 * (z - 1.0) - 1e-3
                     : z > 2.0 ? -1e-2 * (z - 2.0) - 2e-3
                               : -1e-3 * z;
    return Vec3{0.0, 0.0, w};
  });
  EXPECT_NEAR(g.axial, -1e-3, 1e-15);
}

TEST(StrainGauge, AFlatGaugeIsNotValid) {
  std::vector<Vec3> x;  // one layer of particles at the mid-height: no extent along z
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) x.push_back({double(i), double(j), 1.5});
  x.push_back({0, 0, 0});
  x.push_back({0, 0, 3});
  EXPECT_FALSE(StrainGauge(x, {0, 0, 1}, along_z(0.0, 3.0)).valid());
  EXPECT_FALSE(StrainGauge({{0, 0, 0}, {0, 0, 3}}, {0, 0, 1}, along_z(0.0, 3.0)).valid());
}

TEST(StrainGauge, BodyModuliFromTheSlopes) {
  // K = 2000 N/m on A = 1e-4 m^2: 2e7 Pa per metre of travel; the gauge strains -40 per metre.
  const BodyModuli m = body_moduli(2000.0, 1e-4, -40.0, 10.0);
  ASSERT_TRUE(m.valid);
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 5e5);
  EXPECT_DOUBLE_EQ(m.poissons_ratio, 0.25);
  EXPECT_FALSE(body_moduli(2000.0, 1e-4, 0.0, 10.0).valid);  // the body does not shorten
}

}  // namespace
}  // namespace bpm
