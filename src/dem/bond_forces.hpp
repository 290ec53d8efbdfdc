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

/// force and torque = the sums of the end loads of particle p's bonds, in p's adjacency order: one
/// particle's share of the gather (Simulation sums it with the other loads in one pass over the
/// particles). Out-parameters, not a returned struct: GCC kept a returned pair of Vec3 on the
/// stack and the gather took 17-40 % longer.
inline void sum_bond_loads(const BondStore& bonds, std::int64_t p, Vec3& force, Vec3& torque) {
  force = {};
  torque = {};
  const Vec3* moment_of_end[2] = {bonds.end_moment_alpha.data(), bonds.end_moment_beta.data()};
  for (std::int32_t e = bonds.adjacency_start[p]; e < bonds.adjacency_start[p + 1]; ++e) {
    // Without a branch on the end (it alternates unpredictably, as in ContactForces::sum_loads):
    // end beta receives -F_alpha, and x - f equals x + (-1.0 * f) exactly, so the sums are those
    // of the branching loop bit for bit.
    const std::int32_t entry = bonds.adjacency[e];
    const std::int32_t bond = entry >> 1, end = entry & 1;
    const double sign = end == 0 ? 1.0 : -1.0;
    force += sign * bonds.end_force_alpha[bond];
    torque += moment_of_end[end][bond];
  }
}

/// force[p] and torque[p] = sum_bond_loads(bonds, p) for every particle (overwrites).
void gather_bond_loads(ParticleStore& particles, const BondStore& bonds);

}  // namespace bpm
