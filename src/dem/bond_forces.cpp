#include "dem/bond_forces.hpp"

#include <cstdint>

#include "bonds/bond_law.hpp"
#include "core/parallel.hpp"

namespace bpm {

void update_bond_loads(const ParticleStore& particles, BondStore& bonds, double dt) {
  const auto n_bonds = static_cast<std::int64_t>(bonds.size());
  const Vec3* x = particles.position.data();
  const Vec3* v = particles.velocity.data();
  const Vec3* w = particles.angular_velocity.data();
#pragma omp parallel for schedule(static) if (n_bonds > kParallelMinItems)
  for (std::int64_t i = 0; i < n_bonds; ++i) {
    const std::int32_t a = bonds.alpha[i], b = bonds.beta[i];
    const Vec3 d = x[b] - x[a];
    const double length = norm(d);
    const Vec3 n = d * (1.0 / length);
    // The half-step velocities are the chord of the step, so the relative motion is taken in the
    // mid-step configuration d - (v_b - v_a) dt/2. On the end-of-step axis a rigid spin by phi per
    // step would show an axial chord L (1 - cos phi) and ratchet the normal force (first-order
    // energy drift); on the mid-step axis the chord of a rotation has no axial part.
    const Vec3 d_mid = d - (0.5 * dt) * (v[b] - v[a]);
    const double length_mid = norm(d_mid);
    const Vec3 n_mid = d_mid * (1.0 / length_mid);
    Vec3 force = bonds.force[i], moment = bonds.moment[i];
    bond_law::carry_with_bond(force, moment, bonds.axis[i], n, 0.5 * dot(w[a] + w[b], n_mid) * dt);
    const bond_law::RelativeMotion rate = bond_law::relative_motion(
        n_mid, bond_law::contact_arms(length_mid, bonds.arm_offset[i]), v[a], w[a], v[b], w[b]);
    const bond_law::BondLoads increment = bond_law::elastic_response(bonds.stiffness[i], n_mid, rate);
    force += increment.force * dt;
    moment += increment.moment * dt;
    bonds.force[i] = force;
    bonds.moment[i] = moment;
    bonds.axis[i] = n;
    // Viscous bond damping (Chen Eq. 9-10) acts on the rates and is not stored.
    const bond_law::BondLoads total{force + bonds.damping_force[i] * rate.translation,
                                    moment + bonds.damping_moment[i] * rate.rotation};
    const bond_law::EndLoads ends =
        bond_law::transfer_to_centres(n, bond_law::contact_arms(length, bonds.arm_offset[i]), total);
    bonds.end_force_alpha[i] = ends.force_alpha;
    bonds.end_moment_alpha[i] = ends.moment_alpha;
    bonds.end_moment_beta[i] = ends.moment_beta;
  }
}

void gather_bond_loads(ParticleStore& particles, const BondStore& bonds) {
  const auto n_particles = static_cast<std::int64_t>(particles.size());
#pragma omp parallel for schedule(static) if (n_particles > kParallelMinItems)
  for (std::int64_t p = 0; p < n_particles; ++p) {
    Vec3 force, torque;
    for (std::int32_t e = bonds.adjacency_start[p]; e < bonds.adjacency_start[p + 1]; ++e) {
      const std::int32_t entry = bonds.adjacency[e];
      const std::int32_t bond = entry >> 1;
      if ((entry & 1) == 0) {
        force += bonds.end_force_alpha[bond];
        torque += bonds.end_moment_alpha[bond];
      } else {
        force -= bonds.end_force_alpha[bond];
        torque += bonds.end_moment_beta[bond];
      }
    }
    particles.force[p] = force;
    particles.torque[p] = torque;
  }
}

}  // namespace bpm
