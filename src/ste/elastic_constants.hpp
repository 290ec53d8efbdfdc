#pragma once
/// Engineering constants of a Voigt stiffness (voigt.hpp): Young's moduli, Poisson ratios and shear
/// moduli from the compliance S = C^-1, and the Young's modulus along any direction,
/// E_a = 1 / (a a : S : a a).
///
/// The STE's C can be singular: a simple cubic lattice with k_s = 0 has no shear stiffness, yet its
/// E_x = k_n / L is well defined. So the compliance is the pseudo-inverse of the symmetric part
/// (eigenvalues below 1e-12 of the largest are dropped), and a modulus whose stress has a component
/// in C's null space (a mechanism: it cannot be carried) is reported as 0.
#include "core/vec3.hpp"
#include "ste/voigt.hpp"

namespace bpm::ste {

struct EngineeringConstants {
  double E_x = 0.0, E_y = 0.0, E_z = 0.0;  ///< Young's moduli 1/S_11, 1/S_22, 1/S_33, Pa
  /// nu_ij = -S_ji / S_ii: the contraction along j per unit extension along i under uniaxial stress
  /// along i (so nu_ij / E_i = nu_ji / E_j).
  double nu_xy = 0.0, nu_xz = 0.0, nu_yx = 0.0, nu_yz = 0.0, nu_zx = 0.0, nu_zy = 0.0;
  double G_yz = 0.0, G_xz = 0.0, G_xy = 0.0;  ///< shear moduli 1/S_44, 1/S_55, 1/S_66, Pa
};

/// Pseudo-inverse of the symmetric part of C, 1/Pa.
Voigt6 compliance(const Voigt6& c);

EngineeringConstants engineering_constants(const Voigt6& c);

/// Young's modulus along the direction `axis` (need not be unit), Pa; 0 for a mechanism.
double directional_modulus(const Voigt6& c, const Vec3& axis);

/// Poisson's ratio under uniaxial stress along `axis`: the mean contraction across it per unit
/// extension along it, -(tr eps - a.eps.a) / (2 a.eps.a) (what the strain gauges of
/// compress/strain_gauge.hpp measure); 0 for a mechanism.
double directional_poissons_ratio(const Voigt6& c, const Vec3& axis);

/// (E_x, E_y, E_z) by a Cholesky factorisation of the symmetric part, with the pseudo-inverse as
/// the fallback when it is not positive definite (the fast path of the local stiffness map).
Vec3 axis_moduli(const Voigt6& c);

}  // namespace bpm::ste
