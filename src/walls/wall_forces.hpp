#pragma once
/// The particle-wall contact loop: every particle evaluates its contact with each wall in order
/// (contact_law::evaluate with the wall as the rigid partner) and adds it to its own sum; each
/// wall's force is summed over fixed blocks of particles, then over the blocks in order. So
/// particle loads and wall forces are the same for any thread count.
#include <cstdint>
#include <iterator>
#include <vector>

#include "model/contact_material.hpp"
#include "model/particle_store.hpp"
#include "model/wall.hpp"

namespace bpm {

class WallForces {
 public:
  WallForces() = default;
  /// Validates the walls (InputError naming the wall) and sizes their tangential springs.
  WallForces(const ContactTable& table, std::vector<Wall>& walls, const ParticleStore& particles);

  /// Evaluates all particle-wall contacts at the current positions and velocities, advancing the
  /// springs by v_t * increment_dt (0: evaluate only); sets each wall's force.
  void compute(std::vector<Wall>& walls, const ParticleStore& particles, double increment_dt, double dt);

  /// force[p] += force_on(p), torque[p] += torque_on(p), for every particle.
  void gather(ParticleStore& particles) const;

  /// The sums over walls of particle p's wall contact force and moment (0 for a particle the last
  /// compute() did not see).
  Vec3 force_on(std::int64_t p) const { return p < std::ssize(force_) ? force_[p] : Vec3{}; }
  Vec3 torque_on(std::int64_t p) const { return p < std::ssize(torque_) ? torque_[p] : Vec3{}; }

  /// Elastic energy in the particle-wall overlaps and springs, J.
  double elastic_energy(const std::vector<Wall>& walls, const ParticleStore& particles) const;

 private:
  ContactTable table_;
  std::vector<Vec3> force_, torque_;
  std::vector<Vec3> block_sums_;  ///< compute's wall-force sums, per block then wall, kept between steps
};

/// Moves every wall by velocity * dt (point and displacement).
void advance_walls(std::vector<Wall>& walls, double dt);

/// Sets the velocity of every servo-controlled wall from its last force (WallServo).
void control_walls(std::vector<Wall>& walls);

}  // namespace bpm
