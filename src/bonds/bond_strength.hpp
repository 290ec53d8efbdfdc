#pragma once
/// Bond strengths and the parallel-bond failure check (Potyondy & Cundall 2004, the strength part
/// of the parallel bond that Chen 2022 leaves out). A bond breaks, irreversibly, when
///   sigma = F_n / A_b + |M_ben| r_b / I_b   exceeds its tensile strength, or
///   tau   = |F_s| / A_b + |M_tor| r_b / J_b exceeds its shear strength,
/// with F_n > 0 in tension, A_b = pi r_b^2, I_b = pi r_b^4 / 4, J_b = 2 I_b (Chen Eq. 23-24).
/// Multiplied by A_b both become forces: sigma A_b = F_n + 4 |M_ben| / r_b and
/// tau A_b = |F_s| + 2 |M_tor| / r_b, which is what the kernel compares with the stored limits.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "core/vec3.hpp"

namespace bpm {

/// How the strengths of a material's bonds are drawn (seeded, so runs are reproducible).
struct StrengthDistribution {
  enum class Kind { constant, normal, weibull };
  Kind kind = Kind::constant;
  double value =
      std::numeric_limits<double>::infinity();  ///< Pa: constant value, normal mean, Weibull scale
  double spread = 0.0;  ///< normal: standard deviation, Pa; Weibull: shape modulus m (> 0)

  bool breakable() const { return std::isfinite(value); }
  /// One strength, Pa. A normal draw is truncated at zero (a negative strength has no meaning).
  double draw(std::mt19937_64& rng) const;
};

enum class BreakMode : std::uint8_t { tension = 1, shear = 2 };

/// Strength limits of one bond as forces (strength times A_b), N.
struct StrengthLimits {
  double tensile = std::numeric_limits<double>::infinity();
  double shear = std::numeric_limits<double>::infinity();
};

/// sigma / sigma_t and tau / tau_s of the elastic load (F, M) at the contact point: the bond holds
/// while both are at most 1.
struct StrengthUse {
  double tensile = 0.0, shear = 0.0;
};

inline StrengthUse strength_use(const Vec3& n, const Vec3& force, const Vec3& moment,
                                double bond_radius, const StrengthLimits& limits) {
  const double f_n = dot(force, n), m_t = dot(moment, n);
  const double f_s = norm(force - f_n * n), m_b = norm(moment - m_t * n);
  return {(f_n + 4.0 * m_b / bond_radius) / limits.tensile,
          (f_s + 2.0 * std::abs(m_t) / bond_radius) / limits.shear};
}

/// Which criterion the elastic load (F, M) at the contact point violates, if any (0 = none). When
/// both do, the one exceeded by the larger ratio.
inline std::uint8_t failure_mode(const Vec3& n, const Vec3& force, const Vec3& moment,
                                 double bond_radius, const StrengthLimits& limits) {
  const StrengthUse use = strength_use(n, force, moment, bond_radius, limits);
  if (use.tensile <= 1.0 && use.shear <= 1.0) return 0;
  return static_cast<std::uint8_t>(use.tensile >= use.shear ? BreakMode::tension
                                                            : BreakMode::shear);
}

}  // namespace bpm
