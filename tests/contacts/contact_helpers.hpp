#pragma once
// Small contact models for the contact and wall tests: materials, single spheres and random
// packings, and the closed forms the tests compare with.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "model/contact_material.hpp"
#include "model/model.hpp"

namespace bpm::test {

inline ContactMaterial hertz_material(double e_modulus, double nu, double restitution, double friction = 0.0,
                                      double rolling = 0.0) {
  ContactMaterial m;
  m.name = "hertz";
  m.law = ContactLaw::hertz_mindlin;
  m.youngs_modulus = e_modulus;
  m.poisson_ratio = nu;
  m.restitution = restitution;
  m.friction = friction;
  m.rolling_friction = rolling;
  return m;
}

inline ContactMaterial linear_material(double k_n, double k_t, double restitution, double friction = 0.0) {
  ContactMaterial m;
  m.name = "linear";
  m.law = ContactLaw::linear;
  m.k_n = k_n;
  m.k_t = k_t;
  m.restitution = restitution;
  m.friction = friction;
  return m;
}

/// An infinite plane through `point` whose normal points to the particles.
inline Wall plane(const Vec3& point, const Vec3& normal, std::int32_t material) {
  Wall w;
  w.shape = WallShape::plane;
  w.point = point;
  w.normal = normal;
  w.material = material;
  return w;
}

/// Hertz contact duration for an elastic impact at relative normal speed v:
/// t_c = 2 I (5 m* / (4 k))^(2/5) v^(-1/5), k = 4/3 E* sqrt(R*), I = int_0^1 (1 - x^(5/2))^(-1/2) dx
/// = Gamma(2/5) Gamma(1/2) / (5/2 Gamma(9/10)) = 1.4717. That is 2.868 (m*^2/(R* E*^2 v))^(1/5),
/// the "2.87" of the textbooks.
inline double hertz_duration(double m_star, double r_star, double e_star, double v) {
  const double integral = std::tgamma(0.4) * std::tgamma(0.5) / (2.5 * std::tgamma(0.9));
  const double k = 4.0 / 3.0 * e_star * std::sqrt(r_star);
  return 2.0 * integral * std::pow(5.0 * m_star / (4.0 * k), 0.4) * std::pow(v, -0.2);
}

/// Maximum overlap of that impact: (5 m* v^2 / (4 k))^(2/5).
inline double hertz_max_overlap(double m_star, double r_star, double e_star, double v) {
  const double k = 4.0 / 3.0 * e_star * std::sqrt(r_star);
  return std::pow(5.0 * m_star * v * v / (4.0 * k), 0.4);
}

/// Linear spring-dashpot with a force that may not pull (F = max(0, k x + c x')): the rebound
/// leaves when the total force vanishes, x'' = 0, before the overlap does. With x(t) = v/wd e^(-a t)
/// sin(wd t), a = zeta w0, x'' = 0 at wd t = pi - atan(2 a wd / (wd^2 - a^2)); the ratio of exit to
/// impact speed is e^(-a t) (a/wd sin(wd t) - cos(wd t)). Returns {restitution, duration}.
struct LinearImpact {
  double restitution;
  double duration;  ///< until the force vanishes
};
inline LinearImpact linear_impact(double k, double m_star, double e_input) {
  const double l = std::log(e_input);
  const double zeta = -l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
  const double w0 = std::sqrt(k / m_star);
  const double a = zeta * w0, wd = w0 * std::sqrt(1.0 - zeta * zeta);
  const double t = (std::numbers::pi - std::atan(2.0 * a * wd / (wd * wd - a * a))) / wd;
  return {std::exp(-a * t) * (a / wd * std::sin(wd * t) - std::cos(wd * t)), t};
}

/// n spheres with radii in [r_min, r_max] placed at random in a cube of side `side` (overlaps
/// allowed), random velocities |v_k| <= v, angular velocities |w_k| <= w, one material 0.
inline Model random_cloud(int n, double side, double r_min, double r_max, double v, double w, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Model model;
  for (int i = 0; i < n; ++i) {
    const Vec3 x{side * u(rng), side * u(rng), side * u(rng)};
    const std::int32_t k = model.particles.add(i, x, r_min + (r_max - r_min) * u(rng), 2500.0);
    model.particles.velocity[k] = {v * (2 * u(rng) - 1), v * (2 * u(rng) - 1), v * (2 * u(rng) - 1)};
    model.particles.angular_velocity[k] = {w * (2 * u(rng) - 1), w * (2 * u(rng) - 1), w * (2 * u(rng) - 1)};
  }
  return model;
}

}  // namespace bpm::test
