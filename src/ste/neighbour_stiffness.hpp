#pragma once
/// The linear interactions of each particle with its neighbours, as the stiffness tensor
/// estimation sees them (Jarolin Eq. 13: f^nm = K^nm u^nm, u^nm = u^m - u^n, f^nm the force on n):
/// - every intact bond, K^nm = bond_translational_stiffness(k, axis) = R^T diag(k_n, k_s, k_s) R
///   (linear/bond_element.hpp, the unified bond law's translational block with rotations held);
/// - optionally every particle-particle contact at its current overlap, linearised: normal stiffness
///   dF_n/d delta (Hertz 2 E* sqrt(R* delta), linear k_n), tangential k_t (Mindlin
///   8 G* sqrt(R* delta), linear k_t), sticking (sliding is not linearised). Pairs whose material
///   rule is `replace` are skipped while their bond is intact, as in contacts/contact_forces.
/// K of each intact bond is evaluated once (in parallel over bonds) and kept as its 6 independent
/// entries (48 bytes a bond: 0.4 GB for 8e6 bonds); the contacts keep (k_n, k_t).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace bpm::ste {

class NeighbourStiffness {
 public:
  /// Reads the model (positions, bonds, contact materials). Throws InputError if contacts are asked
  /// for and a particle's material has no contact constants.
  NeighbourStiffness(const Model& model, bool include_contacts);

  std::size_t particle_count() const { return particles_; }
  std::size_t intact_bonds() const { return intact_bonds_; }
  std::size_t contacts() const { return contact_start_.back() / 2; }

  /// Calls visit(m, d, K) for each interaction of particle n, in a fixed order (bonds in bond
  /// order, then contacts in pair order): m the neighbour, d = x_m - x_n the branch vector, K the
  /// 3x3 stiffness (symmetric; the same seen from either end).
  template <class Visit>
  void for_each(std::size_t n, Visit&& visit) const {
    const Vec3 xn = x_[n];
    for (std::int32_t e = bond_start_[n]; e < bond_start_[n + 1]; ++e) {
      const std::int32_t entry = bond_adjacency_[static_cast<std::size_t>(e)];
      const auto b = static_cast<std::size_t>(entry >> 1);
      if (check_intact_ && bonds_.intact[b] == 0) continue;
      const std::int32_t m = (entry & 1) == 0 ? bonds_.beta[b] : bonds_.alpha[b];
      const SymmetricK& s = bond_k_[b];
      Eigen::Matrix3d K;
      K << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
      visit(m, x_[static_cast<std::size_t>(m)] - xn, K);
    }
    for (std::size_t k = contact_start_[n]; k < contact_start_[n + 1]; ++k) {
      const Spring& s = springs_[k];
      const Vec3 d = x_[static_cast<std::size_t>(s.partner)] - xn;
      const Vec3 u = d / norm(d);
      const Eigen::Vector3d e(u.x, u.y, u.z);
      const Eigen::Matrix3d K = s.k_t * Eigen::Matrix3d::Identity() + (s.k_n - s.k_t) * (e * e.transpose());
      visit(s.partner, d, K);
    }
  }

 private:
  struct SymmetricK {
    double xx, yy, zz, yz, xz, xy;  ///< N/m
  };
  struct Spring {
    std::int32_t partner;
    double k_n, k_t;  ///< N/m
  };
  void build_contacts(const Model& model);

  const Vec3* x_;
  const BondStore& bonds_;
  std::size_t particles_ = 0;
  bool check_intact_ = false;
  std::size_t intact_bonds_ = 0;
  // Particle -> bond entries (2 * bond + side, BondStore's layout): the store's own adjacency when
  // it is finalised, else built here.
  std::vector<std::int32_t> own_start_, own_adjacency_;
  const std::int32_t* bond_start_ = nullptr;
  const std::int32_t* bond_adjacency_ = nullptr;
  std::vector<SymmetricK> bond_k_;  ///< per bond (zero for a broken one)
  std::vector<std::size_t> contact_start_;
  std::vector<Spring> springs_;
};

}  // namespace bpm::ste
