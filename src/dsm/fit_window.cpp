#include "dsm/fit_window.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace bpm {
namespace {

/// Legendre P_n(t) and its derivative, by the three-term recurrence.
void legendre(int n, double t, double& p, double& dp) {
  double previous = 1.0;
  p = t;
  for (int k = 2; k <= n; ++k) {
    const double next = ((2.0 * k - 1.0) * t * p - (k - 1.0) * previous) / k;
    previous = p;
    p = next;
  }
  dp = n * (t * p - previous) / (t * t - 1.0);  // n >= 2 here
}

void check(int points, int minimum, double fit_from, double fit_to) {
  if (points < minimum || points > 64 || !(fit_from < fit_to)) {
    throw std::invalid_argument("fit window rule: " + std::to_string(points) + " points on [" +
                                std::to_string(fit_from) + ", " + std::to_string(fit_to) + "]");
  }
}

}  // namespace

WindowRule tangent_rule(int points, double fit_from, double fit_to) {
  check(points, 1, fit_from, fit_to);
  // Gauss-Jacobi (1, 1): the nodes are the roots of P'_{n+1}, the inner Gauss-Lobatto nodes of
  // n + 2 points; the Lobatto weights 2 / ((n + 1)(n + 2) P_{n+1}^2) times (1 - t^2) integrate
  // (1 - t^2) g exactly for g up to degree 2n - 1.
  const int n = points + 1;
  const double middle = 0.5 * (fit_from + fit_to), half = 0.5 * (fit_to - fit_from);
  WindowRule rule;
  double total = 0.0;
  for (int i = 1; i <= points; ++i) {
    double t = -std::cos(std::numbers::pi * i / n);  // Chebyshev-Lobatto start, ascending
    double p = 0.0, dp = 0.0;
    for (int it = 0; it < 100;
         ++it) {  // Newton on P'_n: P''_n = (2 t P'_n - n(n+1) P_n) / (1 - t^2)
      legendre(n, t, p, dp);
      const double ddp = (2.0 * t * dp - n * (n + 1.0) * p) / (1.0 - t * t);
      const double step = dp / ddp;
      t -= step;
      if (std::abs(step) < 1e-15) break;
    }
    legendre(n, t, p, dp);
    const double w = (1.0 - t * t) / (p * p);
    rule.travel.push_back(middle + half * t);
    rule.weight.push_back(w);
    total += w;
  }
  for (double& w : rule.weight) w /= total;
  return rule;
}

WindowRule force_rule(int points, double fit_from, double fit_to) {
  check(points, 2, fit_from, fit_to);
  // Gauss-Legendre on [-1, 1]: slope = 12 / (b - a)^3 * h^2 sum w_i t_i F_i = 3 / (2 h) sum w_i t_i
  // F_i, h = (b - a) / 2 in units of the travel.
  const double middle = 0.5 * (fit_from + fit_to), half = 0.5 * (fit_to - fit_from);
  WindowRule rule;
  for (int i = 1; i <= points; ++i) {
    double t = -std::cos(std::numbers::pi * (i - 0.25) / (points + 0.5));
    double p = 0.0, dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      legendre(points, t, p, dp);
      const double step = p / dp;
      t -= step;
      if (std::abs(step) < 1e-15) break;
    }
    legendre(points, t, p, dp);
    if (std::abs(t) < 1e-12) continue;  // the middle node: no weight
    const double w = 2.0 / ((1.0 - t * t) * dp * dp);
    rule.travel.push_back(middle + half * t);
    rule.weight.push_back(1.5 / half * w * t);
  }
  return rule;
}

}  // namespace bpm
