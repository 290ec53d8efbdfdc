#pragma once
/// Broyden's method in two unknowns, the search of the elastic calibration (calibration.hpp, E and
/// nu; its evaluations are smooth, unlike the strength tests' of strength_calibration.hpp): the
/// Newton step on the current Jacobian, and Broyden's rank-one update of it after each evaluation.
/// With one residual it is the secant.
#include <array>
#include <cmath>

namespace bpm {

/// Rows: residuals, columns: unknowns, row-major.
using Jacobian2 = std::array<double, 4>;

/// The step dx with J dx = -f. Without a second residual (`coupled` false), or with |det J| at or
/// below `singular`, the step of the first unknown alone, -f0 / J00, and none in the second.
inline std::array<double, 2> newton_step(const Jacobian2& j, const std::array<double, 2>& f,
                                         bool coupled, double singular) {
  std::array<double, 2> dx{-f[0] / j[0], 0.0};
  if (coupled) {
    const double det = j[0] * j[3] - j[1] * j[2];
    if (std::abs(det) > singular) {
      dx = {(-f[0] * j[3] + f[1] * j[1]) / det, (-f[1] * j[0] + f[0] * j[2]) / det};
    }
  }
  return dx;
}

/// Broyden's update J += (df - J dx) dx^T / |dx|^2 for the step dx that changed the residuals by
/// df. Returns false, leaving J as it was, when dx is zero or the update is not finite.
inline bool broyden_update(Jacobian2& j, const std::array<double, 2>& dx,
                           const std::array<double, 2>& df) {
  const double norm = dx[0] * dx[0] + dx[1] * dx[1];
  const double r0 = df[0] - (j[0] * dx[0] + j[1] * dx[1]);
  const double r1 = df[1] - (j[2] * dx[0] + j[3] * dx[1]);
  if (!(norm > 0.0) || !std::isfinite(r0) || !std::isfinite(r1)) return false;
  j = {j[0] + r0 * dx[0] / norm, j[1] + r0 * dx[1] / norm, j[2] + r1 * dx[0] / norm,
       j[3] + r1 * dx[1] / norm};
  return true;
}

}  // namespace bpm
