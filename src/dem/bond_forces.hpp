#pragma once
/// The DEM bond loop (Chen Table 8, incremental): per-bond end loads, then a per-particle gather.
/// Both loops are race-free and sum in a fixed order, so results do not depend on the thread count.
#include "model/bond_store.hpp"
#include "model/particle_store.hpp"

namespace bpm {

/// Advances every intact bond's stored load by one step of length dt, using the particles' current
/// positions and their velocities over the step, and writes the end loads. Bonds whose load exceeds
/// their strength (bond_strength.hpp) break: they are flagged, unloaded and logged in bonds.breaks.
void update_bond_loads(const ParticleStore& particles, BondStore& bonds, double dt);

/// force[p] and torque[p] = sum of the end loads of p's bonds (overwrites).
void gather_bond_loads(ParticleStore& particles, const BondStore& bonds);

}  // namespace bpm
