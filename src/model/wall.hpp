#pragma once
/// Rigid walls (Jarolin section 2 and 3.1.3: particle-wall interactions, moving walls of the
/// uniaxial compression test). A wall translates with a prescribed velocity, or, with a servo,
/// with a velocity set each step by proportional control of its force. Contacts with particles use
/// the particle contact law (contacts/contact_law.hpp) with the wall's contact material, R* = R,
/// m* = m, and a tangential spring per (particle, wall) pair.
///
/// Each wall records the force the particles exert on it (summed in a fixed order, so the same for
/// any thread count) and its displacement since t = 0: together a force-displacement curve.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

enum class WallShape : std::uint8_t {
  plane,      ///< infinite plane, one-sided: pushes particles to the side `normal` points to
  rectangle,  ///< finite rectangle, two-sided, with edges and corners
  disc,       ///< finite disc, two-sided, with its rim
  cylinder,   ///< infinite circular cylinder about `normal` (the axis); particles inside or outside
};

/// Proportional velocity control of a flat wall (plane, rectangle, disc): each step the wall moves
/// along its normal with v = clamp(gain (F_target - P), -max_speed, max_speed), P = -F . normal the
/// compressive force the particles exert on it. P below the target drives the wall towards the
/// particles. Stable when gain * k_sample * dt << 1 (k_sample the stiffness seen by the wall, N/m):
/// the wall then reaches the target within a few 1/(gain k_sample).
struct WallServo {
  bool enabled = false;
  double target_force = 0.0;  ///< N (compressive)
  double gain = 0.0;          ///< m/(N s)
  double max_speed = std::numeric_limits<double>::infinity();  ///< m/s
};

struct Wall {
  std::string name;
  WallShape shape = WallShape::plane;
  std::int32_t material = 0;  ///< index into ContactModel::materials
  /// plane: a point on it; rectangle, disc: the centre; cylinder: a point on the axis. Moves with
  /// the wall. m
  Vec3 point;
  /// Flat walls: unit normal (plane: towards the particles); cylinder: unit axis.
  Vec3 normal{0.0, 0.0, 1.0};
  Vec3 edge{1.0, 0.0, 0.0};  ///< rectangle: unit direction of its first side, normal to `normal`
  double half_width = 0.0;   ///< rectangle: half length along edge, m
  double half_height = 0.0;  ///< rectangle: half length along normal x edge, m
  double radius = 0.0;       ///< disc, cylinder, m
  bool inside = true;        ///< cylinder: particles inside (true) or outside
  Vec3 velocity;             ///< m/s; set by the servo when it is enabled
  WallServo servo;

  // State of a run.
  Vec3 displacement;  ///< since t = 0, m
  Vec3 force;         ///< force the particles exert on the wall in the last evaluation, N
  std::vector<Vec3> spring;  ///< tangential spring per particle, m (sized by the simulation)
};

namespace wall_geometry {

/// Contact of a sphere (centre x, radius r) with a wall: unit normal from the centre towards the
/// wall, overlap (> 0 in contact) and the distance from the centre to the contact point.
struct Gap {
  Vec3 n;
  double overlap = 0.0;  ///< m
  double arm = 0.0;      ///< m
};

/// Nearest point q of the wall to x; the contact normal is (q - x)/|q - x|.
inline Gap towards_point(const Vec3& x, double r, const Vec3& q, const Vec3& fallback_n) {
  const Vec3 d = q - x;
  const double dist = norm(d);
  return {dist > 0.0 ? d * (1.0 / dist) : fallback_n, r - dist, dist};
}

inline Gap gap(const Wall& w, const Vec3& x, double r) {
  const Vec3 d = x - w.point;
  const double s = dot(d, w.normal);  // signed height above the plane / position along the axis
  switch (w.shape) {
    case WallShape::plane:
      return {-w.normal, r - s, std::max(s, 0.0)};
    case WallShape::rectangle: {
      const Vec3 e2 = cross(w.normal, w.edge);
      const double u = std::clamp(dot(d, w.edge), -w.half_width, w.half_width);
      const double v = std::clamp(dot(d, e2), -w.half_height, w.half_height);
      return towards_point(x, r, w.point + u * w.edge + v * e2, s >= 0.0 ? -w.normal : w.normal);
    }
    case WallShape::disc: {
      Vec3 in_plane = d - s * w.normal;
      const double rho = norm(in_plane);
      if (rho > w.radius) in_plane *= w.radius / rho;
      return towards_point(x, r, w.point + in_plane, s >= 0.0 ? -w.normal : w.normal);
    }
    case WallShape::cylinder: {
      const Vec3 radial = d - s * w.normal;
      const double rho = norm(radial);
      if (!(rho > 0.0)) return {};  // on the axis: no defined normal (and no contact unless r > R_c)
      const Vec3 out = radial * (1.0 / rho);
      return w.inside ? Gap{out, r - (w.radius - rho), w.radius - rho} : Gap{-out, r - (rho - w.radius), rho - w.radius};
    }
  }
  return {};
}

}  // namespace wall_geometry

}  // namespace bpm
