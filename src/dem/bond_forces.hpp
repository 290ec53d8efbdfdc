#pragma once
/// The DEM bond loop (Chen Table 8, incremental): per-bond end loads, then a per-particle gather.
/// Both loops are race-free and sum in a fixed order, so results do not depend on the thread count.
#include <cstdint>

#include "model/bond_store.hpp"
#include "model/particle_store.hpp"

namespace bpm {

/// Advances every intact bond's stored load by one step of length dt, using the particles' current
/// positions and their velocities over the step, and writes the end loads. Bonds whose load exceeds
/// their strength (bond_strength.hpp) break: they are flagged, unloaded and logged in bonds.breaks.
void update_bond_loads(const ParticleStore& particles, BondStore& bonds, double dt);

/// The sum of the end loads of particle p's bonds, in p's adjacency order: one particle's share of
/// the gather (Simulation sums it with the other loads in one pass over the particles).
inline ParticleLoad bond_loads_on(const BondStore& bonds, std::int64_t p) {
  ParticleLoad sum;
  for (std::int32_t e = bonds.adjacency_start[p]; e < bonds.adjacency_start[p + 1]; ++e) {
    const std::int32_t entry = bonds.adjacency[e];
    const std::int32_t bond = entry >> 1;
    if ((entry & 1) == 0) {
      sum.force += bonds.end_force_alpha[bond];
      sum.torque += bonds.end_moment_alpha[bond];
    } else {
      sum.force -= bonds.end_force_alpha[bond];
      sum.torque += bonds.end_moment_beta[bond];
    }
  }
  return sum;
}

/// force[p] and torque[p] = bond_loads_on(bonds, p) for every particle (overwrites).
void gather_bond_loads(ParticleStore& particles, const BondStore& bonds);

}  // namespace bpm
