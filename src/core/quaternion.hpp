#pragma once
/// Unit quaternion for particle orientation (w, x, y, z), with the two operations the integrator
/// and the output need: advance by an angular velocity over a step, and convert to a rotation
/// vector with atan2 (accurate for small angles, unlike acos of w).
#include <cmath>

#include "core/vec3.hpp"

namespace bpm {

struct Quat {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

constexpr Quat operator*(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

/// q <- exp(theta/2) * q, theta = omega * dt in the global frame; renormalised each step.
inline Quat advance(const Quat& q, const Vec3& theta) {
  const double angle = norm(theta);
  Quat dq;
  if (angle > 0.0) {
    const double s = std::sin(0.5 * angle) / angle;
    dq = {std::cos(0.5 * angle), theta.x * s, theta.y * s, theta.z * s};
  }
  Quat r = dq * q;
  const double inv = 1.0 / std::sqrt(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
  return {r.w * inv, r.x * inv, r.y * inv, r.z * inv};
}

/// Rotation vector (axis * angle, angle in [0, pi]) of a unit quaternion.
inline Vec3 rotation_vector(const Quat& q) {
  const Vec3 v{q.x, q.y, q.z};
  const double s = norm(v);
  if (s == 0.0) return {};
  const double w = q.w < 0 ? -q.w : q.w;
  const double sign = q.w < 0 ? -1.0 : 1.0;
  return v * (sign * 2.0 * std::atan2(s, w) / s);
}

}  // namespace bpm
