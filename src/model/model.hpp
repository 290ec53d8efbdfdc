#pragma once
/// Everything a DEM run needs besides its time step and stop criteria: the particles and bonds,
/// the external loads, gravity and damping, and the particle contacts and walls (both off by
/// default: no contact materials, no walls).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "model/contact_material.hpp"
#include "model/bond_store.hpp"
#include "model/particle_store.hpp"
#include "model/wall.hpp"

namespace bpm {

/// A force and moment applied to each particle of a set, ramped linearly from zero over ramp_time
/// and then held (Chen section 3: 100 kN/s for 1 s, then constant).
struct Load {
  std::vector<std::int32_t> particles;
  Vec3 force;   ///< N, per particle, at full value
  Vec3 moment;  ///< N m, per particle, at full value
  double ramp_time = 0.0;  ///< s; 0 applies the full value at once

  double factor(double t) const { return ramp_time > 0.0 ? std::min(t / ramp_time, 1.0) : 1.0; }
};

struct Damping {
  double particle = 0.0;  ///< gamma_b, Chen Eq. 11-12 ("local damping"); 0 switches it off
  double bond = 0.0;      ///< eta_b, Chen Eq. 9-10 (viscous bond damping); 0 switches it off
};

struct Model {
  ParticleStore particles;
  BondStore bonds;
  std::vector<Load> loads;
  Vec3 gravity;
  Damping damping;
  /// Particle-particle contacts (off unless contacts.particle_particle is set) and the contact
  /// materials that particles (by ParticleStore::material) and walls (by Wall::material) use.
  ContactModel contacts;
  std::vector<Wall> walls;

  /// Fixes the given degrees of freedom of particle p (mask entries 0 = fixed) at velocity zero.
  void fix(std::int32_t p, const Vec3& translation_fixed, const Vec3& rotation_fixed);
  /// Finalises the bonds (axes, damping coefficients, adjacency); call once before simulating.
  void finalize() { bonds.finalize(particles, damping.bond); }
};

}  // namespace bpm
