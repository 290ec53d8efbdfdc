// Radius distributions: bounds, means and spreads of the draws, table fractions by number and by
// volume, and reproducibility for a seed.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "structure/radius_distribution.hpp"

namespace bpm {
namespace {

std::vector<double> draw(const RadiusDistribution& d, int n, std::uint64_t seed = 1) {
  std::mt19937_64 rng(seed);
  RadiusSampler sample(d);
  std::vector<double> r(static_cast<std::size_t>(n));
  for (double& x : r) x = sample(rng);
  return r;
}

double mean(const std::vector<double>& x) {
  double s = 0.0;
  for (const double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double stddev(const std::vector<double>& x) {
  const double m = mean(x);
  double s = 0.0;
  for (const double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / static_cast<double>(x.size() - 1));
}

constexpr int kN = 100000;

TEST(RadiusDistribution, Monodisperse) {
  for (const double r : draw(RadiusDistribution::monodisperse(0.3), 100)) EXPECT_EQ(r, 0.3);
}

TEST(RadiusDistribution, UniformMeanAndBounds) {
  const auto r = draw(RadiusDistribution::uniform(1.0, 3.0), kN);
  for (const double x : r) EXPECT_TRUE(x >= 1.0 && x <= 3.0);
  // mean 2, std 2/sqrt(12): 5 standard errors
  EXPECT_NEAR(mean(r), 2.0, 5.0 * (2.0 / std::sqrt(12.0)) / std::sqrt(kN));
  EXPECT_NEAR(stddev(r), 2.0 / std::sqrt(12.0), 0.01);
}

TEST(RadiusDistribution, NormalTruncatedAtThreeSigma) {
  const auto d = RadiusDistribution::normal(1.0, 0.1);
  EXPECT_DOUBLE_EQ(d.min, 0.7);
  EXPECT_DOUBLE_EQ(d.max, 1.3);
  const auto r = draw(d, kN);
  for (const double x : r) EXPECT_TRUE(x >= 0.7 && x <= 1.3);
  EXPECT_NEAR(mean(r), 1.0, 5.0 * 0.1 / std::sqrt(kN));
  EXPECT_NEAR(stddev(r), 0.1 * 0.9866, 0.002);  // SD of a normal truncated at +-3 sigma
}

TEST(RadiusDistribution, NormalWideIsClippedAboveZero) {
  const auto d = RadiusDistribution::normal(1.0, 1.0);  // default lower bound 1e-3 mean
  for (const double x : draw(d, 10000)) EXPECT_GE(x, 1e-3);
}

TEST(RadiusDistribution, LognormalMeanAndStd) {
  const auto d = RadiusDistribution::lognormal(2.0, 0.2, 1e-6, 100.0);  // (almost) untruncated
  const auto r = draw(d, kN);
  EXPECT_NEAR(mean(r), 2.0, 5.0 * 0.2 / std::sqrt(kN));
  EXPECT_NEAR(stddev(r), 0.2, 0.004);
  for (const double x : r) EXPECT_GT(x, 0.0);
}

TEST(RadiusDistribution, TableByNumberAndByVolume) {
  // By number: 1 m with probability 0.25, 2 m with 0.75.
  auto counts = [](const std::vector<double>& r) {
    std::map<double, int> c;
    for (const double x : r) ++c[x];
    return c;
  };
  const auto by_number = counts(draw(RadiusDistribution::table({1.0, 2.0}, {1.0, 3.0}, false), kN));
  const double sd = std::sqrt(kN * 0.25 * 0.75);
  EXPECT_NEAR(by_number.at(1.0), 0.25 * kN, 5 * sd);
  // By volume, equal shares of 1 m and 2 m spheres: 8 times as many small ones (number 8/9).
  const auto by_volume = counts(draw(RadiusDistribution::table({1.0, 2.0}, {0.5, 0.5}, true), kN));
  const double sd2 = std::sqrt(kN * (8.0 / 9.0) * (1.0 / 9.0));
  EXPECT_NEAR(by_volume.at(1.0), 8.0 / 9.0 * kN, 5 * sd2);
}

TEST(RadiusDistribution, SameSeedSameRadiiOtherSeedOthers) {
  const auto d = RadiusDistribution::lognormal(1.0, 0.3);
  EXPECT_EQ(draw(d, 1000, 42), draw(d, 1000, 42));
  EXPECT_NE(draw(d, 1000, 42), draw(d, 1000, 43));
}

}  // namespace
}  // namespace bpm
