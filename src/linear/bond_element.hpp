#pragma once
/// The linearised bond element: the 12x12 stiffness that maps the end displacements and rotations
/// (d_alpha, theta_alpha, d_beta, theta_beta; Chen Eq. 15-16) to the bond's restoring loads,
/// f = -K u (Chen Eq. 13). It is built column by column from the same bond_law functions the DEM
/// kernel calls, so the DEM, the static solver and (later) the DSM and STE share one law. For TBBM
/// along x it is the Timoshenko beam element of Chen Eq. 14 and 17-22.
#include <Eigen/Core>
#include <cstddef>

#include "bonds/bond_law.hpp"

namespace bpm {

struct ParticleStore;
struct BondStore;

using ElementMatrix = Eigen::Matrix<double, 12, 12>;

ElementMatrix bond_element_stiffness(const BondStiffness& k, const Vec3& n, bond_law::Arms arms);

/// The translational block of the element with both rotations held (Jarolin Eq. 6-8): the force a
/// bond exerts on alpha per unit translation of beta relative to alpha, R^T diag(k_n, k_s, k_s) R.
/// The 3-DOF direct stiffness method and the stiffness tensor estimation use this 3x3 matrix.
Eigen::Matrix3d bond_translational_stiffness(const BondStiffness& k, const Vec3& n);

/// Element of bond i at the particles' current positions.
ElementMatrix bond_element_stiffness(const ParticleStore& particles, const BondStore& bonds,
                                     std::size_t i);

/// The six rows of one end's DOFs (end 0: alpha, 1: beta) of bond i's element: by the element's
/// symmetry (the law is elastic), the transposed columns of that end's six unit motions, half the
/// work of the whole element. An assembly that builds each particle's rows needs only these.
using ElementRows = Eigen::Matrix<double, 6, 12>;
ElementRows bond_element_rows(const ParticleStore& particles, const BondStore& bonds, std::size_t i,
                              int end);

}  // namespace bpm
