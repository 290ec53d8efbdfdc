#pragma once
/// A particle-particle contact as a linear element of the direct stiffness method: the contact law
/// linearised at the pair's overlap (contact_law::linearise), normal stiffness k_n = dF_n/d delta
/// along n and the no-slip tangential stiffness k_t across it (Jarolin section 3.1.2), acting at
/// the contact point, which lies the arms a_i, a_j from the centres along n (the DEM's: R - delta/2).
///
/// With q = (u_i, theta_i, u_j, theta_j), the relative displacement of j's surface point against
/// i's is Delta = B q = u_j + [a_j n]x theta_j - u_i + [a_i n]x theta_i, the force on i is C Delta
/// with C = k_n n n^T + k_t (I - n n^T), and the element is B^T C B (symmetric, positive
/// semi-definite). With 3 DOF per particle the rotations are dropped: [C -C; -C C] in the leading
/// 6x6 block.
#include "core/vec3.hpp"
#include "linear/bond_element.hpp"

namespace bpm {

struct ContactElement {
  std::int32_t i = 0, j = 0;
  Vec3 n;                       ///< unit normal i -> j
  double arm_i = 0.0, arm_j = 0.0;  ///< m
  double k_n = 0.0, k_t = 0.0;      ///< N/m
};

inline ElementMatrix contact_element_stiffness(const ContactElement& c, int dofs) {
  const Eigen::Vector3d n(c.n[0], c.n[1], c.n[2]);
  const Eigen::Matrix3d C = c.k_n * n * n.transpose() + c.k_t * (Eigen::Matrix3d::Identity() - n * n.transpose());
  ElementMatrix k = ElementMatrix::Zero();
  if (dofs == 3) {
    k.block<3, 3>(0, 0) = C;
    k.block<3, 3>(0, 3) = -C;
    k.block<3, 3>(3, 0) = -C;
    k.block<3, 3>(3, 3) = C;
    return k;
  }
  auto skew = [](const Eigen::Vector3d& v) {
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return s;
  };
  Eigen::Matrix<double, 3, 12> B;
  B << -Eigen::Matrix3d::Identity(), skew(c.arm_i * n), Eigen::Matrix3d::Identity(), skew(c.arm_j * n);
  k = B.transpose() * C * B;
  return k;
}

}  // namespace bpm
