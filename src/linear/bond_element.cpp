#include "linear/bond_element.hpp"

#include "model/bond_store.hpp"
#include "model/particle_store.hpp"

namespace bpm {

namespace {

/// Column j of the element: minus the loads on (alpha, beta) for the unit motion j of
/// (d_alpha, theta_alpha, d_beta, theta_beta).
template <typename Column>
void element_column(const BondStiffness& k, const Vec3& n, bond_law::Arms arms, int j, Column&& column) {
  Vec3 u[4];
  u[j / 3][j % 3] = 1.0;
  const auto motion = bond_law::relative_motion(n, arms, u[0], u[1], u[2], u[3]);
  const auto ends = bond_law::transfer_to_centres(n, arms, bond_law::elastic_response(k, n, motion));
  const Vec3 f[4] = {ends.force_alpha, ends.moment_alpha, -ends.force_alpha, ends.moment_beta};
  for (int i = 0; i < 12; ++i) column(i) = -f[i / 3][i % 3];
}

}  // namespace

ElementMatrix bond_element_stiffness(const BondStiffness& k, const Vec3& n, bond_law::Arms arms) {
  ElementMatrix K;
  for (int j = 0; j < 12; ++j) element_column(k, n, arms, j, [&](int i) -> double& { return K(i, j); });
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

ElementRows bond_element_rows(const ParticleStore& particles, const BondStore& bonds, std::size_t i,
                              int end) {
  const Vec3 d = particles.position[bonds.beta[i]] - particles.position[bonds.alpha[i]];
  const double length = norm(d);
  const bond_law::Arms arms = bond_law::contact_arms(length, bonds.arm_offset[i]);
  ElementRows rows;
  for (int k = 0; k < 6; ++k) {
    element_column(bonds.stiffness[i], d / length, arms, 6 * end + k, [&](int j) -> double& { return rows(k, j); });
  }
  return rows;
}

}  // namespace bpm
