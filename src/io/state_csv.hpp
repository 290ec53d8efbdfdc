#pragma once
/// The final state of every particle as CSV, one row per particle in store order:
/// id, x, y, z (m), ux, uy, uz (displacement from the reference position, m), rx, ry, rz (rotation
/// vector of the orientation, rad), vx, vy, vz (m/s), wx, wy, wz (rad/s), fx, fy, fz (total force
/// of the last evaluation, N; on a fixed particle, the negative of the support reaction).
#include <string>

#include "model/particle_store.hpp"

namespace bpm {

std::string state_csv(const ParticleStore& particles);

/// Writes state_csv atomically.
void write_state_csv(const std::string& path, const ParticleStore& particles);

}  // namespace bpm
