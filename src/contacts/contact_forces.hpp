#pragma once
/// The particle-particle contact loop, organised like the bond loop (dem/bond_forces.hpp): a pass
/// over the listed pairs in which each pair writes only its own slots (force on i, torques on i and
/// j), then a per-particle gather over a CSR adjacency in pair order. No atomics, and the same sums
/// for any thread count.
///
/// Bonded pairs follow their material pair's BondedContacts rule: `superimpose` lets the contact act
/// beside the bond whenever the particles overlap; `replace` switches the contact off while the
/// bond is intact (BondStore::intact), and a broken bond hands the pair to the contact law.
#include <cstdint>
#include <vector>

#include "contacts/contact_law.hpp"
#include "model/contact_material.hpp"
#include "contacts/neighbour_list.hpp"
#include "model/bond_store.hpp"
#include "model/particle_store.hpp"

namespace bpm {

class ContactForces {
 public:
  ContactForces() = default;
  /// Checks that every particle's material has contact constants (InputError otherwise). skin <= 0
  /// picks 0.1 * the largest radius.
  ContactForces(const ContactTable& table, const ParticleStore& particles, double skin);

  /// Rebuilds the neighbour list when some particle has moved half the skin; the tangential springs
  /// of pairs found in both lists are carried over, matched by (i, j). Returns true on a rebuild.
  bool update_list(const ParticleStore& particles, const BondStore& bonds);

  /// Evaluates every listed pair at the current positions and velocities (the half-step velocities
  /// in the DEM loop), advancing the tangential springs by v_t * increment_dt (0: evaluate only).
  void compute(const ParticleStore& particles, const BondStore& bonds, double increment_dt, double dt);

  /// force[p] += the sum_loads force of p, torque[p] likewise, for every particle.
  void gather(ParticleStore& particles) const;

  /// force and torque = the sums of particle p's contact loads, in pair order: one particle's
  /// share of the gather (Simulation sums it with the other loads in one pass over the particles;
  /// out-parameters as in sum_bond_loads). Valid once compute() has run on the current list
  /// (gathered() says so).
  void sum_loads(std::int64_t p, Vec3& force, Vec3& torque) const {
    force = {};
    torque = {};
    const Vec3* torque_of_side[2] = {torque_i_.data(), torque_j_.data()};
    for (std::int32_t e = adjacency_start_[p]; e < adjacency_start_[p + 1]; ++e) {
      // Without a branch on the side (it alternates unpredictably): j receives -force, and x - f
      // equals x + (-1.0 * f) exactly, so the sums are those of the branching loop bit for bit.
      const std::int32_t entry = adjacency_[e];
      const std::int32_t pair = entry >> 1, side = entry & 1;
      const double sign = side == 0 ? 1.0 : -1.0;
      force += sign * force_i_[pair];
      torque += torque_of_side[side][pair];
    }
  }
  /// Whether sum_loads can be called for each of `particles` particles.
  bool gathered(std::size_t particles) const { return adjacency_start_.size() == particles + 1; }

  /// Elastic energy in the current overlaps and tangential springs, J.
  double elastic_energy() const;

  const NeighbourList& list() const { return list_; }
  const ContactTable& table() const { return table_; }
  /// Per listed pair: tangential spring (m), force on i (N; j gets the opposite), torques on i and
  /// j (N m), normal force (N, 0 when not touching or switched off by a bond).
  const std::vector<Vec3>& spring() const { return spring_; }
  const std::vector<Vec3>& force() const { return force_i_; }
  const std::vector<Vec3>& torque_i() const { return torque_i_; }
  const std::vector<Vec3>& torque_j() const { return torque_j_; }
  const std::vector<double>& normal_force() const { return normal_force_; }
  /// Number of pairs with a contact force in the last evaluation.
  std::int64_t touching() const;

  /// The contact history, for checkpoints (scenario/checkpoint.hpp): the list and, per listed pair, the
  /// tangential spring and the loads of the last evaluation.
  struct History {
    NeighbourList::State list;
    std::vector<Vec3> spring, force_i, torque_i, torque_j;
    std::vector<double> normal_force, overlap;
  };
  History history() const;
  /// Continues from `history`; the pair-to-bond links and the gather order are derived again.
  void restore(History history, const ParticleStore& particles, const BondStore& bonds);

 private:
  contact_law::PairInertia inertia(const ParticleStore& p, std::int32_t i, std::int32_t j,
                                   const ContactPairParameters& c) const;
  bool switched_off(const BondStore& bonds, std::size_t pair, const ContactPairParameters& c) const;
  /// The bond of each listed pair, its constants and the particle -> pairs adjacency, from the list.
  void link_pairs(const ParticleStore& particles, const BondStore& bonds);

  ContactTable table_;
  double skin_ = 0.0;
  NeighbourList list_;
  std::vector<Vec3> spring_, force_i_, torque_i_, torque_j_;
  std::vector<double> normal_force_, overlap_;
  std::vector<std::int32_t> bond_;  ///< bond joining the pair, -1 if none
  /// Per listed pair, from the particles' radii, masses and materials at the last list build
  /// (fixed during a run): the material pair's index in table_, R*, m*, I* and the dashpot
  /// factors. The loop reads them in pair order instead of partner j's rows.
  std::vector<std::int32_t> pair_material_;
  std::vector<contact_law::PairInertia> pair_inertia_;
  std::vector<contact_law::Dashpots> pair_dashpots_;
  std::vector<std::int32_t> adjacency_start_, adjacency_;  ///< entries 2 * pair + side (1: p is j)
};

}  // namespace bpm
