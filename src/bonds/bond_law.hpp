#pragma once
/// Chen's unified bond law (Chen 2022, Eq. 4-7 and Table 8), written once and used by the DEM
/// kernel, the linearised 12x12 element (and through it the static solver). Stateless inline
/// functions: the loops that call them live elsewhere.
///
/// Conventions (one reading of Chen's garbled signs, derived from the physics):
/// - n is the unit bond axis from particle alpha to particle beta (Chen's e_x).
/// - The contact point x_c sits a_alpha along n from alpha and a_beta back from beta, with
///   a_alpha + a_beta = L (current length) so both particles agree on x_c; that equality is what
///   makes the moments balance, so angular momentum is conserved to round-off.
/// - Relative motion is beta minus alpha at x_c (Chen writes alpha minus beta with e_x reversed).
/// - The bond load (F_b, M_b) is what the bond exerts on alpha at x_c; beta receives the opposite.
#include "bonds/bond_stiffness.hpp"
#include "core/vec3.hpp"

namespace bpm::bond_law {

/// Distances from the particle centres to the contact point along n.
struct Arms {
  double alpha = 0.0;
  double beta = 0.0;
};

/// Contact-point rule as data: a_alpha = L/2 + offset. Chen Table 9: offset 0 for the beam models
/// (beam centre, Eq. 44); (R_alpha - R_beta)/2 for the parallel bond (gap centre, Eq. 1-2).
inline Arms contact_arms(double length, double offset) {
  return {0.5 * length + offset, 0.5 * length - offset};
}

/// Relative translation and rotation of beta with respect to alpha at the contact point: rates when
/// given velocities, increments when given displacements (Chen Eq. 4-7).
struct RelativeMotion {
  Vec3 translation;
  Vec3 rotation;
};

inline RelativeMotion relative_motion(const Vec3& n, Arms arms, const Vec3& u_alpha,
                                      const Vec3& theta_alpha, const Vec3& u_beta,
                                      const Vec3& theta_beta) {
  const Vec3 r_alpha_c = arms.alpha * n;
  const Vec3 r_beta_c = -arms.beta * n;
  return {(u_beta + cross(theta_beta, r_beta_c)) - (u_alpha + cross(theta_alpha, r_alpha_c)),
          theta_beta - theta_alpha};
}

/// k_axial along n, k_transverse across it: the local-frame diagonal stiffness written without a
/// frame (the y and z stiffnesses are equal in every model, so only the axis matters).
inline Vec3 split_stiffness(double k_axial, double k_transverse, const Vec3& n, const Vec3& u) {
  return k_transverse * u + ((k_axial - k_transverse) * dot(n, u)) * n;
}

/// Load at the contact point (on alpha). Chen Table 8: dF_c = (k_n, k_s, k_s) dd,
/// dM_c = (k_tor, k_ben, k_ben) dtheta in the local frame.
struct BondLoads {
  Vec3 force;
  Vec3 moment;
};

inline BondLoads elastic_response(const BondStiffness& k, const Vec3& n, const RelativeMotion& d) {
  return {split_stiffness(k.k_n, k.k_s, n, d.translation),
          split_stiffness(k.k_tor, k.k_ben, n, d.rotation)};
}

/// Loads at the particle centres (Chen Table 8, right column): the force acts equal and opposite,
/// and each particle takes the moment plus the lever arm of the force.
struct EndLoads {
  Vec3 force_alpha;  ///< force on alpha; beta receives -force_alpha
  Vec3 moment_alpha;
  Vec3 moment_beta;
};

inline EndLoads transfer_to_centres(const Vec3& n, Arms arms, const BondLoads& c) {
  const Vec3 n_x_f = cross(n, c.force);
  return {c.force, c.moment + arms.alpha * n_x_f, -c.moment + arms.beta * n_x_f};
}

/// Carries the stored bond load along with the bond over one step, before the increment is added:
/// first the minimal rotation taking the old axis onto the new one (rigid swing of the bond), then
/// the twist about the new axis by the mean spin of the two particles, psi = (omega_a + omega_b)/2
/// . n dt. Both are exact rotations given by Gibbs vectors (tan(angle/2) * axis), so no acos and no
/// round-off floor; for the twist tan(psi/2) is taken as psi/2, an O(psi^3) error per step far below
/// the O(dt^2) of the integrator. The two are composed into one Gibbs vector (Rodrigues: twist t2
/// after swing t1 is (t1 + t2 + t2 x t1) / (1 - t1 . t2), and t1 . t2 = 0 because the swing axis is
/// normal to the new axis), so force and moment are each rotated once.
inline void carry_with_bond(Vec3& force, Vec3& moment, const Vec3& n_old, const Vec3& n_new,
                            double twist_angle) {
  // One reciprocal instead of three divisions (the DEM kernel runs this for every bond and step).
  const Vec3 swing = cross(n_old, n_new) * (1.0 / (1.0 + dot(n_old, n_new)));
  const Vec3 twist = (0.5 * twist_angle) * n_new;
  const GibbsRotation carry(swing + twist + cross(twist, swing));
  force = carry(force);
  moment = carry(moment);
}

/// Elastic energy stored in a bond with load (F, M): 1/2 F K^-1 F + 1/2 M K^-1 M, componentwise in
/// the local frame. A zero stiffness stores no energy (its load cannot build up).
inline double elastic_energy(const BondStiffness& k, const Vec3& n, const Vec3& force,
                             const Vec3& moment) {
  auto part = [](double value_sq, double stiffness) {
    return stiffness > 0.0 ? 0.5 * value_sq / stiffness : 0.0;
  };
  const double f_n = dot(force, n), m_n = dot(moment, n);
  return part(f_n * f_n, k.k_n) + part(norm2(force) - f_n * f_n, k.k_s) +
         part(m_n * m_n, k.k_tor) + part(norm2(moment) - m_n * m_n, k.k_ben);
}

}  // namespace bpm::bond_law
