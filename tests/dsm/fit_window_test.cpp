// The fit-window rules (dsm/fit_window.hpp) against the least-squares slope they stand for,
// computed here by brute force: Simpson's rule on the continuous least-squares slope.
#include "dsm/fit_window.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>

namespace bpm {
namespace {

constexpr double kFrom = 0.2, kTo = 1.0;

/// The least-squares slope of F over [kFrom, kTo] (continuous: 12 / (b - a)^3 times the integral of
/// (w - m) F), the integral by Simpson's rule on 200,000 intervals.
double fitted_slope(const std::function<double(double)>& F) {
  const int n = 200000;
  const double h = (kTo - kFrom) / n, m = 0.5 * (kFrom + kTo);
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = kFrom + h * i;
    sum += (i == 0 || i == n ? 1.0 : i % 2 == 1 ? 4.0 : 2.0) * (w - m) * F(w);
  }
  return 12.0 / std::pow(kTo - kFrom, 3) * sum * h / 3.0;
}

double tangent_estimate(const WindowRule& rule, const std::function<double(double)>& dF) {
  double slope = 0.0;
  for (std::size_t i = 0; i < rule.travel.size(); ++i) slope += rule.weight[i] * dF(rule.travel[i]);
  return slope;
}

double force_estimate(const WindowRule& rule, const std::function<double(double)>& F) {
  double slope = 0.0;
  for (std::size_t i = 0; i < rule.travel.size(); ++i) slope += rule.weight[i] * F(rule.travel[i]);
  return slope;
}

TEST(FitWindow, TwoTangentNodesAreTheClassicalRule) {
  const WindowRule rule = tangent_rule(2, kFrom, kTo);
  ASSERT_EQ(rule.travel.size(), 2u);
  const double middle = 0.6, node = 0.4 / std::sqrt(5.0);
  EXPECT_NEAR(rule.travel[0], middle - node, 1e-14);
  EXPECT_NEAR(rule.travel[1], middle + node, 1e-14);
  EXPECT_NEAR(rule.weight[0], 0.5, 1e-14);
  EXPECT_NEAR(rule.weight[1], 0.5, 1e-14);
}

TEST(FitWindow, TangentRuleIsExactForPolynomialsOfDegree2nMinus1) {
  for (int points : {1, 2, 3, 4, 8}) {
    const WindowRule rule = tangent_rule(points, kFrom, kTo);
    EXPECT_NEAR(std::accumulate(rule.weight.begin(), rule.weight.end(), 0.0), 1.0, 1e-13);
    const int degree = 2 * points - 1;  // of F'; F has one more
    auto F = [&](double w) { return std::pow(w, degree + 1) / (degree + 1) + 3.0 * w; };
    auto dF = [&](double w) { return std::pow(w, degree) + 3.0; };
    EXPECT_NEAR(tangent_estimate(rule, dF), fitted_slope(F), 1e-8) << points << " points";
  }
}

TEST(FitWindow, ForceRuleIsExactForPolynomialsOfDegree2n) {
  // The three-point rule needs F at two nodes (the middle one has no weight), as the nonlinear
  // DSM has always done: slope = sqrt(5/3) (F(m + d) - F(m - d)) / (b - a).
  const WindowRule three = force_rule(3, kFrom, kTo);
  ASSERT_EQ(three.travel.size(), 2u);
  EXPECT_NEAR(three.weight[1], std::sqrt(5.0 / 3.0) / (kTo - kFrom), 1e-13);
  EXPECT_NEAR(three.weight[0], -three.weight[1], 1e-13);
  for (int points : {2, 3, 5, 9}) {
    const WindowRule rule = force_rule(points, kFrom, kTo);
    EXPECT_NEAR(std::accumulate(rule.weight.begin(), rule.weight.end(), 0.0), 0.0, 1e-12);
    const int degree = 2 * points - 2;  // (w - m) F is integrated exactly up to degree 2 n - 1
    auto F = [&](double w) { return std::pow(w, degree) - 2.0 * w; };
    EXPECT_NEAR(force_estimate(rule, F), fitted_slope(F), 1e-8) << points << " points";
  }
}

TEST(FitWindow, MoreTangentNodesFollowAKinkedCurve) {
  // A spring that starts touching at w0 inside the window: F' = k for w > w0 (a linear spring)
  // or 1.5 c sqrt(w - w0) (Hertz). Two nodes miss it; the error falls as nodes are added.
  auto dF = [](double w) { return 1.0 + (w > 0.45 ? 1.5 * std::sqrt(w - 0.45) : 0.0); };
  auto F = [](double w) { return w + (w > 0.45 ? std::pow(w - 0.45, 1.5) : 0.0); };
  const double exact = fitted_slope(F);
  const double two = std::abs(tangent_estimate(tangent_rule(2, kFrom, kTo), dF) - exact);
  const double eight = std::abs(tangent_estimate(tangent_rule(8, kFrom, kTo), dF) - exact);
  EXPECT_LT(eight, 0.2 * two);
  EXPECT_LT(eight / exact, 2e-3);
}

TEST(FitWindow, BadArgumentsThrow) {
  EXPECT_THROW(tangent_rule(0, kFrom, kTo), std::invalid_argument);
  EXPECT_THROW(force_rule(1, kFrom, kTo), std::invalid_argument);
  EXPECT_THROW(tangent_rule(2, kTo, kFrom), std::invalid_argument);
}

}  // namespace
}  // namespace bpm
