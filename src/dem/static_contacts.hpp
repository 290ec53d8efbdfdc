#pragma once
/// The particle pairs that the static methods (the direct stiffness method, the stiffness tensor
/// estimation) treat as contacts, listed once from the initial positions (Jarolin section 3.1.2:
/// "determine the neighboring particles only once in advance"). The bonded-pair rule of the DEM's
/// contact loop applies (contact_law::contact_acts): a pair joined by an intact bond whose material
/// pair says `replace` is left out.
#include <cstdint>
#include <vector>

#include "contacts/contact_law.hpp"
#include "model/model.hpp"

namespace bpm {

struct StaticContact {
  std::int32_t i = 0, j = 0;  ///< i < j
  Vec3 n;                     ///< unit normal from i to j at the start
  double overlap = 0.0;       ///< R_i + R_j - |x_j - x_i| at the start, m (< 0: a gap)
  ContactPairParameters params;
  contact_law::PairInertia inertia;
};

/// Pairs whose surface gap is below `gap` (m; > 0), in the neighbour list's order (the same for
/// any thread count). Empty when the scenario has no particle-particle contacts.
std::vector<StaticContact> list_static_contacts(const Model& model, double gap);

}  // namespace bpm
