#include "linear/bond_element.hpp"

#include "model/bond_store.hpp"
#include "model/particle_store.hpp"

namespace bpm {

ElementMatrix bond_element_stiffness(const BondStiffness& k, const Vec3& n, bond_law::Arms arms) {
  ElementMatrix K;
  for (int j = 0; j < 12; ++j) {
    Vec3 u[4];  // d_alpha, theta_alpha, d_beta, theta_beta
    u[j / 3][j % 3] = 1.0;
    const auto motion = bond_law::relative_motion(n, arms, u[0], u[1], u[2], u[3]);
    const auto ends = bond_law::transfer_to_centres(n, arms, bond_law::elastic_response(k, n, motion));
    const Vec3 f[4] = {ends.force_alpha, ends.moment_alpha, -ends.force_alpha, ends.moment_beta};
    for (int i = 0; i < 12; ++i) K(i, j) = -f[i / 3][i % 3];
  }
  return K;
}

Eigen::Matrix3d bond_translational_stiffness(const BondStiffness& k, const Vec3& n) {
  Eigen::Matrix3d K;
  for (int j = 0; j < 3; ++j) {
    Vec3 relative;
    relative[j] = 1.0;
    const Vec3 f = bond_law::elastic_response(k, n, {relative, {}}).force;
    for (int i = 0; i < 3; ++i) K(i, j) = f[i];
  }
  return K;
}

ElementMatrix bond_element_stiffness(const ParticleStore& particles, const BondStore& bonds,
                                     std::size_t i) {
  const Vec3 d = particles.position[bonds.beta[i]] - particles.position[bonds.alpha[i]];
  const double length = norm(d);
  return bond_element_stiffness(bonds.stiffness[i], d / length,
                                bond_law::contact_arms(length, bonds.arm_offset[i]));
}

}  // namespace bpm
