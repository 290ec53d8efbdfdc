#pragma once
/// The particle contact law (Jarolin section 2: Hertz-Mindlin after Mindlin & Deresiewicz with the
/// damping of Tsuji et al. 1992; and a linear spring-dashpot), as stateless inline functions. The
/// loops over particle pairs (contacts/contact_forces.cpp) and over particle-wall pairs
/// (walls/wall_forces.cpp) call the same `evaluate`; the law is chosen by data (the pair's
/// ContactLaw), one switch per contact, no virtual calls.
///
/// Conventions:
/// - n is the unit normal from body i towards body j; the overlap delta > 0 in contact.
/// - v_rel is the velocity of j relative to i at the contact point; w_roll = omega_i - omega_j.
/// - The returned force acts on i at the contact point; j receives the opposite force. The rolling
///   torque acts on i; j receives the opposite torque.
/// - The tangential spring s (m) is the accumulated tangential displacement of j relative to i,
///   stored per contact. Each step it is turned into the current tangent plane (its normal part is
///   removed and its length kept), incremented by v_t dt, and read as F_t = k_t s. On sliding it is
///   scaled back so that k_t s equals the Coulomb force.
/// - The normal force F_n = elastic + damping acts while the bodies overlap. Near the end of a
///   rebound the dashpot may pull (F_n < 0), as in Tsuji et al. and the damped oscillator their
///   beta comes from: then the rebound speed is e times the impact speed (exactly for the linear
///   law, within a few per cent for Hertz). With ContactPairParameters::no_tension the total force
///   is clamped at zero instead (no pulling, the bodies part when it vanishes): the rebound is then
///   faster than e (closed form for the linear law in tests/contacts/contact_helpers.hpp).
///   Friction and rolling friction use max(F_n, 0).
#include <algorithm>
#include <cmath>

#include "core/vec3.hpp"
#include "model/contact_material.hpp"

namespace bpm::contact_law {

/// Reduced radius, mass and moment of inertia of the pair (R*, m*, I*; a wall is rigid: R, m, I).
struct PairInertia {
  double r_star = 0.0;  ///< m
  double m_star = 0.0;  ///< kg
  double i_star = 0.0;  ///< kg m^2
};

struct Kinematics {
  Vec3 n;                ///< unit normal, i -> j
  double overlap = 0.0;  ///< delta, m (> 0 in contact)
  Vec3 v_rel;            ///< velocity of j relative to i at the contact point, m/s
  Vec3 w_roll;           ///< omega_i - omega_j, rad/s (rolling friction only)
};

struct ContactLoad {
  Vec3 force;                 ///< on i at the contact point, N; j receives -force
  Vec3 rolling_torque;        ///< on i, N m; j receives -rolling_torque
  double normal_force = 0.0;  ///< F_n, N (> 0 pushes the bodies apart)
};

/// Normal elastic force, normal and tangential stiffness and the dashpot coefficients at overlap
/// delta.
struct Stiffness {
  double f_elastic = 0.0;  ///< N
  double k_t = 0.0;        ///< N/m
  double c_n = 0.0;        ///< N s/m (>= 0)
  double c_t = 0.0;        ///< N s/m (>= 0)
};

/// The parts of the dashpot coefficients that depend on the pair only (R*, m* and the materials):
/// Hertz c = factor (R* delta)^(1/4) (factor in N s m^-3/2), linear c = factor (N s/m). Constant
/// while two particles stay listed, so the contact loop computes them at list builds and the law
/// takes one square root per step for both dashpots instead of two.
struct Dashpots {
  double normal = 0.0;
  double tangential = 0.0;
};

inline Dashpots dashpots(const ContactPairParameters& p, const PairInertia& g) {
  if (p.law == ContactLaw::hertz_mindlin) {
    // Tsuji et al. 1992: F^d = -2 sqrt(5/6) beta sqrt(S m*) v, beta = ln e / sqrt(ln^2 e + pi^2),
    // with S_n = 2 E* sqrt(R* delta) and S_t = 8 G* sqrt(R* delta): sqrt(S m*) is
    // sqrt(2 E* m*) (R* delta)^(1/4) and sqrt(8 G* m*) (R* delta)^(1/4).
    constexpr double kTsuji = 1.8257418583505538;  // 2 sqrt(5/6)
    return {-kTsuji * p.beta * std::sqrt(2.0 * p.e_star * g.m_star),
            -kTsuji * p.beta * std::sqrt(8.0 * p.g_star * g.m_star)};
  }
  // Linear spring-dashpot: damping ratio zeta = -beta gives e exactly for the free oscillator,
  // c = 2 zeta sqrt(k m*).
  return {-2.0 * p.beta * std::sqrt(p.k_n * g.m_star), -2.0 * p.beta * std::sqrt(p.k_t * g.m_star)};
}

inline Stiffness stiffness(const ContactPairParameters& p, const PairInertia& g, const Dashpots& c,
                           double delta) {
  Stiffness s;
  if (p.law == ContactLaw::hertz_mindlin) {
    const double root = std::sqrt(g.r_star * delta);
    s.f_elastic = (4.0 / 3.0) * p.e_star * root * delta;  // Hertz: 4/3 E* sqrt(R*) delta^1.5
    s.k_t = 8.0 * p.g_star * root;           // Mindlin: k_t = S_t = 8 G* sqrt(R* delta)
    const double quarter = std::sqrt(root);  // (R* delta)^(1/4), see Dashpots
    s.c_n = c.normal * quarter;
    s.c_t = c.tangential * quarter;
  } else {
    s.f_elastic = p.k_n * delta;
    s.k_t = p.k_t;
    s.c_n = c.normal;
    s.c_t = c.tangential;
  }
  return s;
}

inline Stiffness stiffness(const ContactPairParameters& p, const PairInertia& g, double delta) {
  return stiffness(p, g, dashpots(p, g), delta);
}

/// The elastic law linearised at overlap delta: the one place the static methods (the DSM's
/// platen springs and contact elements, the STE's contact springs and platen series) and the
/// contact time step take contact stiffnesses from. All zero when the bodies do not overlap.
struct Linearised {
  double force = 0.0;           ///< elastic normal force F_n, N
  double normal_tangent = 0.0;  ///< dF_n/d delta, N/m (Hertz: 2 E* sqrt(R* delta) = 3/2 F_n/delta)
  double normal_secant = 0.0;   ///< F_n / delta, N/m
  double tangential = 0.0;      ///< k_t, N/m (Mindlin: 8 G* sqrt(R* delta); no slip)
};

/// F_n grows as delta^exponent: 1.5 (Hertz) or 1 (linear), so F_n(delta) = F_n(1 m) delta^exponent.
inline double normal_exponent(const ContactPairParameters& p) {
  return p.law == ContactLaw::hertz_mindlin ? 1.5 : 1.0;
}

inline Linearised linearise(const ContactPairParameters& p, const PairInertia& g, double delta) {
  if (!(delta > 0.0)) return {};
  const Stiffness s = stiffness(p, g, delta);
  const double secant = s.f_elastic / delta;
  return {s.f_elastic, normal_exponent(p) * secant, secant, s.k_t};
}

/// The tangential force of the static methods: the spring k_t stretched by s along a monotonic load
/// path (no history: the DEM's spring of `evaluate` built up in one step), capped at the Coulomb
/// force mu F_n as `evaluate` caps it when the contact slides.
inline Vec3 coulomb_capped(const ContactPairParameters& p, double k_t, double normal_force,
                           const Vec3& s) {
  const Vec3 f = k_t * s;
  const double limit = p.friction * std::max(normal_force, 0.0);
  const double size = norm(f);
  return size > limit ? f * (limit / size) : f;
}

/// Jarolin section 2: a bond superimposes the contact of the pair it joins, or replaces it while
/// it is intact. The one statement of that rule, for the DEM's contact loop and the static methods.
inline bool contact_acts(const ContactPairParameters& p, bool intact_bond_between) {
  return !(intact_bond_between && p.bonded == BondedContacts::replace);
}

/// Elastic energy stored in a contact, J: normal part exactly (Hertz: 2/5 F_e delta = 8/15 E*
/// sqrt(R*) delta^2.5; linear: 1/2 k_n delta^2), tangential part 1/2 k_t |s|^2.
inline double elastic_energy(const ContactPairParameters& p, const PairInertia& g, double delta,
                             const Vec3& spring) {
  if (!(delta > 0.0)) return 0.0;
  const Stiffness s = stiffness(p, g, delta);
  const double normal =
      p.law == ContactLaw::hertz_mindlin ? 0.4 * s.f_elastic * delta : 0.5 * s.f_elastic * delta;
  return normal + 0.5 * s.k_t * norm2(spring);
}

/// One contact over one step: updates the tangential spring (by v_t * increment_dt; pass 0 to
/// evaluate the force of the current state without advancing it) and returns the loads.
/// dt is the time step, used only to keep the rolling torque from reversing the relative rolling
/// within a step (see below); 0 leaves the torque uncapped.
/// `c` are the pair's dashpots(p, g), passed by loops that keep them per pair.
inline ContactLoad evaluate(const ContactPairParameters& p, const PairInertia& g, const Dashpots& c,
                            const Kinematics& k, Vec3& spring, double increment_dt, double dt) {
  const Vec3& n = k.n;
  const double v_n = dot(k.v_rel, n);  // > 0: separating
  const Vec3 v_t = k.v_rel - v_n * n;
  const Stiffness s = stiffness(p, g, c, k.overlap);

  ContactLoad out;
  out.normal_force = s.f_elastic - s.c_n * v_n;  // overlap rate is -v_n
  if (p.no_tension) out.normal_force = std::max(0.0, out.normal_force);
  const double pressing = std::max(0.0, out.normal_force);

  // Turn the stored spring into the current tangent plane, keeping its length: one square root of
  // the ratio of the squared lengths instead of two lengths.
  const double length_sq = norm2(spring);
  spring -= dot(spring, n) * n;
  const double projected_sq = norm2(spring);
  if (projected_sq > 0.0) spring *= std::sqrt(length_sq / projected_sq);
  spring += v_t * increment_dt;

  Vec3 f_t = s.k_t * spring + s.c_t * v_t;
  const double limit = p.friction * pressing;  // Coulomb: |F_t| <= mu F_n
  // Compared squared: a sticking contact (most of them in a quasi-static run) takes no square root.
  const double f_t_sq = norm2(f_t);
  if (f_t_sq > limit * limit) {
    // Sliding: the force is the Coulomb force along the trial direction, the spring holds it all
    // (the dashpot is off while sliding; friction does the dissipation).
    const double f_t_norm = std::sqrt(f_t_sq);
    f_t = f_t_norm > 0.0 ? f_t * (limit / f_t_norm) : Vec3{};
    spring = s.k_t > 0.0 ? f_t / s.k_t : Vec3{};
  }
  out.force = f_t - out.normal_force * n;

  if (p.rolling_friction > 0.0) {
    // Rolling friction as a constant directional torque mu_r R* F_n against the relative rolling
    // (EDEM's "type A"). Left alone it chatters once the rolling stops (the sign of omega flips
    // every step); capping it at I* |omega_r| / dt, the torque that stops the relative rolling in
    // one step, removes the chatter and leaves a rolling-free contact at rest.
    const Vec3 w_r = k.w_roll - dot(k.w_roll, n) * n;
    const double w = norm(w_r);
    if (w > 0.0) {
      double torque = p.rolling_friction * g.r_star * pressing;
      if (dt > 0.0) torque = std::min(torque, g.i_star * w / dt);
      out.rolling_torque = w_r * (-torque / w);
    }
  }
  return out;
}

inline ContactLoad evaluate(const ContactPairParameters& p, const PairInertia& g,
                            const Kinematics& k, Vec3& spring, double increment_dt, double dt) {
  return evaluate(p, g, dashpots(p, g), k, spring, increment_dt, dt);
}

}  // namespace bpm::contact_law
