#pragma once
/// Voigt notation for the stiffness tensor estimation (STE). Order 11, 22, 33, 23, 13, 12:
///   strain e = (eps_11, eps_22, eps_33, gamma_23, gamma_13, gamma_12), gamma_ij = 2 eps_ij;
///   stress s = (sigma_11, sigma_22, sigma_33, sigma_23, sigma_13, sigma_12);
/// so s = C e with C the 6x6 Voigt stiffness (Pa) and e = S s with S = C^-1 the compliance (1/Pa).
/// With this pairing s.e is the work per unit volume and a major-symmetric C_ijkl gives a symmetric
/// 6x6 matrix.
#include <Eigen/Core>

#include "core/vec3.hpp"

namespace bpm::ste {

using Voigt6 = Eigen::Matrix<double, 6, 6>;
using Voigt6Vector = Eigen::Matrix<double, 6, 1>;
/// A 3x6 map from a Voigt strain to a displacement (or a fluctuation, Jarolin Eq. 22-29).
using StrainMap = Eigen::Matrix<double, 3, 6>;

/// D(d): the affine relative displacement eps . d of two centres a branch vector d apart, as a map
/// of the Voigt strain (Jarolin Eq. 17, first term). Its transpose maps a force f to the Voigt
/// form of the symmetrised dyad d (x) f (Jarolin Eq. 12), which is why the STE can be written with
/// D alone: C^n = 1/(2 V^n) sum_m D^T K A.
inline StrainMap affine_map(const Vec3& d) {
  StrainMap m = StrainMap::Zero();
  m(0, 0) = d.x;
  m(1, 1) = d.y;
  m(2, 2) = d.z;
  m(1, 3) = 0.5 * d.z;
  m(2, 3) = 0.5 * d.y;
  m(0, 4) = 0.5 * d.z;
  m(2, 4) = 0.5 * d.x;
  m(0, 5) = 0.5 * d.y;
  m(1, 5) = 0.5 * d.x;
  return m;
}

/// K D(d) for a 3x3 K, written out (column by column from D's 9 non-zeros).
inline StrainMap times_affine_map(const Eigen::Matrix3d& k, const Vec3& d) {
  StrainMap m;
  m.col(0) = d.x * k.col(0);
  m.col(1) = d.y * k.col(1);
  m.col(2) = d.z * k.col(2);
  m.col(3) = 0.5 * (d.z * k.col(1) + d.y * k.col(2));
  m.col(4) = 0.5 * (d.z * k.col(0) + d.x * k.col(2));
  m.col(5) = 0.5 * (d.y * k.col(0) + d.x * k.col(1));
  return m;
}

/// D(d)^T M for a 3x6 M, written out (D has 9 non-zeros; this is the hot product of the STE).
inline Voigt6 affine_map_transpose_times(const Vec3& d, const StrainMap& m) {
  Voigt6 r;
  r.row(0) = d.x * m.row(0);
  r.row(1) = d.y * m.row(1);
  r.row(2) = d.z * m.row(2);
  r.row(3) = 0.5 * (d.z * m.row(1) + d.y * m.row(2));
  r.row(4) = 0.5 * (d.z * m.row(0) + d.x * m.row(2));
  r.row(5) = 0.5 * (d.y * m.row(0) + d.x * m.row(1));
  return r;
}

/// The Voigt stress of a unit uniaxial stress along the unit vector a: (a a) in Voigt form. Then
/// 1/E_a = u^T S u (the normal strain along a per unit stress), the directional Young's modulus.
inline Voigt6Vector uniaxial_stress(const Vec3& a) {
  Voigt6Vector u;
  u << a.x * a.x, a.y * a.y, a.z * a.z, a.y * a.z, a.x * a.z, a.x * a.y;
  return u;
}

}  // namespace bpm::ste
