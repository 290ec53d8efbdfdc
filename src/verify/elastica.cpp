#include "verify/elastica.hpp"

#include <array>
#include <cmath>

namespace bpm::verify {
namespace {

/// State (theta, theta', v) along the normalised arc length s in [0, 1]; v = tip deflection / L.
using State = std::array<double, 3>;

State integrate(double alpha, double curvature_at_root) {
  constexpr int kSteps = 2000;
  constexpr double h = 1.0 / kSteps;
  auto rate = [alpha](const State& y) -> State { return {y[1], -alpha * std::cos(y[0]), std::sin(y[0])}; };
  auto axpy = [](const State& y, double a, const State& k) -> State {
    return {y[0] + a * k[0], y[1] + a * k[1], y[2] + a * k[2]};
  };
  State y{0.0, curvature_at_root, 0.0};
  for (int i = 0; i < kSteps; ++i) {
    const State k1 = rate(y), k2 = rate(axpy(y, 0.5 * h, k1)), k3 = rate(axpy(y, 0.5 * h, k2)),
                k4 = rate(axpy(y, h, k3));
    for (int j = 0; j < 3; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
  return y;
}

}  // namespace

double elastica_tip_ratio(double alpha) {
  if (alpha <= 0.0) return 1.0;
  // theta'(1) (the tip moment) increases with the root curvature; it is negative at 0 and positive
  // at 2 alpha (the linear root curvature is alpha).
  double lo = 0.0, hi = 2.0 * alpha;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (integrate(alpha, mid)[1] > 0.0 ? hi : lo) = mid;
  }
  return integrate(alpha, 0.5 * (lo + hi))[2] / (alpha / 3.0);
}

}  // namespace bpm::verify
