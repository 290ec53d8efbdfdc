#pragma once
/// A small 3-vector of doubles for the hot loops: trivially copyable, no virtuals, header-only, so
/// the same kernels could later be compiled for a device without change. Eigen is used where
/// matrices are needed (elements, assembly); this type keeps the particle arrays plain.
#include <bit>
#include <cmath>
#include <cstdint>

namespace bpm {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;

  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
};

constexpr Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
constexpr Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(Vec3 a, double s) { return a *= s; }
constexpr Vec3 operator*(double s, Vec3 a) { return a *= s; }
constexpr Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
constexpr bool operator==(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Component-wise product (used for per-DOF masks such as fixed directions).
constexpr Vec3 hadamard(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
constexpr double norm2(const Vec3& a) { return dot(a, a); }
inline double norm(const Vec3& a) { return std::sqrt(norm2(a)); }
constexpr double max_abs(const Vec3& a) {
  const double ax = a.x < 0 ? -a.x : a.x, ay = a.y < 0 ? -a.y : a.y, az = a.z < 0 ? -a.z : a.z;
  return ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
}
/// True when v is (+0, +0, +0) bit for bit, the value a contact out of touch stores: a loop can
/// skip the store that would write it again.
constexpr bool all_bits_zero(const Vec3& v) {
  return (std::bit_cast<std::uint64_t>(v.x) | std::bit_cast<std::uint64_t>(v.y) |
          std::bit_cast<std::uint64_t>(v.z)) == 0;
}

/// A rotation given by its Gibbs vector t = tan(angle/2) * axis. The map is exactly orthogonal for
/// any t (no trigonometry, no acos), which keeps incremental rotations free of the round-off floor
/// that acos(cos) near 1 would leave. The scale 2/(1 + t.t) is computed once per rotation.
struct GibbsRotation {
  Vec3 t;
  double scale;

  constexpr explicit GibbsRotation(const Vec3& gibbs) : t(gibbs), scale(2.0 / (1.0 + norm2(gibbs))) {}

  constexpr Vec3 operator()(const Vec3& v) const {
    const Vec3 tv = cross(t, v);
    return v + scale * (tv + cross(t, tv));
  }
};

}  // namespace bpm
