#include "dem/bond_forces.hpp"

#include <cstdint>

#include "bonds/bond_law.hpp"
#include "bonds/bond_strength.hpp"
#include "core/parallel.hpp"

namespace bpm {

namespace {

/// The bond loop. Without breakable bonds the strength check compiles away.
template <bool kBreakable>
bool update_bond_loads_impl(const ParticleStore& particles, BondStore& bonds, double dt) {
  const auto n_bonds = static_cast<std::int64_t>(bonds.size());
  const Vec3* x = particles.position.data();
  const Vec3* v = particles.velocity.data();
  const Vec3* w = particles.angular_velocity.data();
  bool any_broke = false;
#pragma omp parallel for schedule(static) reduction(|| : any_broke) if (n_bonds > kParallelMinItems)
  for (std::int64_t i = 0; i < n_bonds; ++i) {
    if constexpr (kBreakable) {
      if (bonds.intact[i] != 1) continue;  // its end loads were zeroed when it broke
    }
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
    bonds.axis[i] = n;
    if constexpr (kBreakable) {
      if (const std::uint8_t mode = failure_mode(n, force, moment, bonds.radius[i], bonds.strength[i])) {
        bonds.intact[i] = 2;  // recorded (and set to 0) by record_breaks after the loop
        bonds.break_mode[i] = mode;
        bonds.force[i] = bonds.moment[i] = Vec3{};
        bonds.end_force_alpha[i] = bonds.end_moment_alpha[i] = bonds.end_moment_beta[i] = Vec3{};
        any_broke = true;
        continue;
      }
    }
    bonds.force[i] = force;
    bonds.moment[i] = moment;
    // Viscous bond damping (Chen Eq. 9-10) acts on the rates and is not stored.
    const bond_law::BondLoads total{force + bonds.damping_force[i] * rate.translation,
                                    moment + bonds.damping_moment[i] * rate.rotation};
    const bond_law::EndLoads ends =
        bond_law::transfer_to_centres(n, bond_law::contact_arms(length, bonds.arm_offset[i]), total);
    bonds.end_force_alpha[i] = ends.force_alpha;
    bonds.end_moment_alpha[i] = ends.moment_alpha;
    bonds.end_moment_beta[i] = ends.moment_beta;
  }
  return any_broke;
}

/// Logs the bonds the last update broke, in bond order (so the log is the same for any thread count).
void record_breaks(const ParticleStore& particles, BondStore& bonds) {
  for (std::size_t i = 0; i < bonds.size(); ++i) {
    if (bonds.intact[i] != 2) continue;
    bonds.intact[i] = 0;
    const Vec3 xa = particles.position[bonds.alpha[i]], xb = particles.position[bonds.beta[i]];
    const double length = norm(xb - xa);
    const bond_law::Arms arms = bond_law::contact_arms(length, bonds.arm_offset[i]);
    bonds.breaks.push_back({static_cast<std::int32_t>(i), bonds.updates,
                            static_cast<BreakMode>(bonds.break_mode[i]),
                            xa + (arms.alpha / length) * (xb - xa)});
  }
}

}  // namespace

void update_bond_loads(const ParticleStore& particles, BondStore& bonds, double dt) {
  ++bonds.updates;
  if (!bonds.breakable) {
    update_bond_loads_impl<false>(particles, bonds, dt);
  } else if (update_bond_loads_impl<true>(particles, bonds, dt)) {
    record_breaks(particles, bonds);
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
