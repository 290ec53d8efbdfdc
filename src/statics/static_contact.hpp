#pragma once
/// The one contact of the static methods (the DSM, the STE, the static core): a particle pair, or
/// a particle and a plane wall (a platen), listed once from the initial positions (Jarolin section
/// 3.1.2: "determine the neighboring particles only once in advance") with a constant normal.
///
/// The contact point is the DEM's (contacts/contact_forces.cpp): in the middle of the overlap, the
/// arms a = R - delta_0/2 from the centres along n. With q = (u_i, theta_i, u_j, theta_j), the
/// displacement of j's surface point relative to i's is
///   Delta = u_j + [a_j n]x theta_j - u_i + [a_i n]x theta_i      (a wall: u_j = its motion, no
///   spin),
/// the overlap is delta_0 - n.Delta, and a linearised contact acts on i with C Delta,
/// C = k_n n n^T + k_t (I - n n^T): the element B^T C B (symmetric, positive semi-definite). With 3
/// DOF per particle the rotations are dropped (Jarolin Eq. 6-8).
#include <cstdint>
#include <vector>

#include "contacts/contact_law.hpp"
#include "linear/bond_element.hpp"
#include "model/model.hpp"

namespace bpm {

struct StaticContact {
  std::int32_t i = 0;
  std::int32_t j = -1;   ///< the partner particle (> i), or -1: a wall
  Vec3 n;                ///< unit normal from i towards j (or towards the wall)
  double overlap = 0.0;  ///< delta_0: R_i + R_j - |x_j - x_i| (a wall: -gap) at the start, m
  double arm_i = 0.0, arm_j = 0.0;  ///< m (the DEM's R - delta_0/2; arm_j = 0 for a wall)
  Vec3 wall_motion;  ///< a wall's displacement per metre of platen travel (zero: it is held)
  ContactPairParameters params;
  contact_law::PairInertia inertia;
  double k_n = 0.0, k_t = 0.0;  ///< the linearised law at the operating point, N/m

  bool wall() const { return j < 0; }
};

/// Pairs whose surface gap is below `gap` (m; > 0), in the neighbour list's order (the same for any
/// thread count), k_n and k_t linearised at their initial overlap. The bonded-pair rule of the
/// DEM's contact loop applies (contact_law::contact_acts): a pair joined by an intact bond whose
/// material pair says `replace` is left out. Empty when the scenario has no particle-particle
/// contacts.
std::vector<StaticContact> list_static_contacts(const Model& model, double gap);

/// The contact of particle i with a plane wall of contact material `wall_material` whose normal
/// (towards the sample) is `wall_normal`, at surface gap `gap` (m), moving `wall_motion` per metre
/// of travel.
StaticContact wall_contact(const Model& model, std::int32_t i, std::int32_t wall_material,
                           const Vec3& wall_normal, double gap, const Vec3& wall_motion);

/// Sets k_n = dF_n/d delta and the no-slip k_t of the contact law at overlap delta (zero apart).
void linearise_at(StaticContact& c, double delta);

/// The contact's element B^T C B (the header above) in the dofs (6 or 3) per end layout; a
/// wall's is the leading dofs x dofs block.
ElementMatrix contact_element_stiffness(const StaticContact& c, int dofs);

}  // namespace bpm
