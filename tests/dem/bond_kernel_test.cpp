// The blocked, vectorised bond kernel (bond_forces.cpp) against a plain per-bond loop written from
// bond_law.hpp, as the kernel was before it was blocked: the same loads to round-off, for a bond
// count that leaves a partial last block. And a bond's result must not depend on where it sits in
// its block: the same bonds stored in another order give bitwise the same loads.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "bonds/bond_law.hpp"
#include "dem/bond_forces.hpp"
#include "dem_helpers.hpp"

namespace bpm {
namespace {

struct Loads {
  std::vector<Vec3> force, moment, axis, end_force_alpha, end_moment_alpha, end_moment_beta;
};

Loads loads_of(const BondStore& b) {
  return {b.force, b.moment, b.axis, b.end_force_alpha, b.end_moment_alpha, b.end_moment_beta};
}

/// One update of every bond, one bond at a time (the kernel's loop before blocking).
void reference_update(const ParticleStore& p, BondStore& bonds, double dt) {
  for (std::size_t i = 0; i < bonds.size(); ++i) {
    const std::int32_t a = bonds.alpha[i], b = bonds.beta[i];
    const Vec3 d = p.position[b] - p.position[a];
    const double length = norm(d);
    const Vec3 n = d / length;
    const Vec3 d_mid = d - (0.5 * dt) * (p.velocity[b] - p.velocity[a]);
    const Vec3 n_mid = d_mid / norm(d_mid);
    const Vec3 &w_a = p.angular_velocity[a], &w_b = p.angular_velocity[b];
    bond_law::carry_with_bond(bonds.force[i], bonds.moment[i], bonds.axis[i], n,
                              0.5 * dot(w_a + w_b, n_mid) * dt);
    const bond_law::RelativeMotion rate =
        bond_law::relative_motion(n_mid, bond_law::contact_arms(norm(d_mid), bonds.arm_offset[i]),
                                  p.velocity[a], w_a, p.velocity[b], w_b);
    const bond_law::BondLoads increment =
        bond_law::elastic_response(bonds.stiffness[i], n_mid, rate);
    bonds.force[i] += increment.force * dt;
    bonds.moment[i] += increment.moment * dt;
    bonds.axis[i] = n;
    const bond_law::BondLoads total{bonds.force[i] + bonds.damping_force[i] * rate.translation,
                                    bonds.moment[i] + bonds.damping_moment[i] * rate.rotation};
    const bond_law::EndLoads ends = bond_law::transfer_to_centres(
        n, bond_law::contact_arms(length, bonds.arm_offset[i]), total);
    bonds.end_force_alpha[i] = ends.force_alpha;
    bonds.end_moment_alpha[i] = ends.moment_alpha;
    bonds.end_moment_beta[i] = ends.moment_beta;
  }
}

/// Moves the particles by one step of their velocities (the kernel only needs a changing state).
void drift(ParticleStore& p, double dt) {
  for (std::size_t i = 0; i < p.size(); ++i) p.position[i] += dt * p.velocity[i];
}

double largest(const std::vector<Vec3>& values) {
  double m = 0.0;
  for (const Vec3& v : values) m = std::max(m, max_abs(v));
  return m;
}

void expect_close(const std::vector<Vec3>& got, const std::vector<Vec3>& want, const char* what) {
  const double scale = largest(want);
  ASSERT_GT(scale, 0.0) << what;
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_LE(max_abs(got[i] - want[i]), 1e-12 * scale) << what << " of bond " << i;
  }
}

// 30 unequal spheres (PBM: a non-zero contact-point offset), 29 bonds: three full blocks of 8 and
// a partial one; bond damping on.
Model chain() {
  Model model = test::free_chain(30, "pbm", 0.05, 50.0, 7);
  model.damping.bond = 0.1;
  model.finalize();
  return model;
}

TEST(BondKernelTest, MatchesThePerBondLoop) {
  Model model = chain();
  BondStore reference = model.bonds;
  const double dt = 1e-7;
  for (int step = 0; step < 20; ++step) {
    drift(model.particles, dt);
    update_bond_loads(model.particles, model.bonds, dt);
    reference_update(model.particles, reference, dt);
  }
  expect_close(model.bonds.force, reference.force, "force");
  expect_close(model.bonds.moment, reference.moment, "moment");
  expect_close(model.bonds.axis, reference.axis, "axis");
  expect_close(model.bonds.end_force_alpha, reference.end_force_alpha, "end force");
  expect_close(model.bonds.end_moment_alpha, reference.end_moment_alpha, "end moment alpha");
  expect_close(model.bonds.end_moment_beta, reference.end_moment_beta, "end moment beta");
}

TEST(BondKernelTest, BondOrderDoesNotChangeABondsLoads) {
  Model model = chain();
  // The same bonds rotated by 3 places: every bond lands in another lane (and some in the tail).
  const std::size_t n = model.bonds.size();
  BondStore rotated;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (k + 3) % n;
    rotated.add(model.bonds.alpha[i], model.bonds.beta[i],
                {model.bonds.stiffness[i], model.bonds.arm_offset[i]}, model.bonds.radius[i],
                model.bonds.rest_length[i]);
  }
  rotated.finalize(model.particles, model.damping.bond);
  const double dt = 1e-7;
  for (int step = 0; step < 20; ++step) {
    drift(model.particles, dt);
    update_bond_loads(model.particles, model.bonds, dt);
    update_bond_loads(model.particles, rotated, dt);
  }
  const Loads in_order = loads_of(model.bonds), other = loads_of(rotated);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (k + 3) % n;
    EXPECT_EQ(other.force[k], in_order.force[i]) << "bond " << i;
    EXPECT_EQ(other.moment[k], in_order.moment[i]) << "bond " << i;
    EXPECT_EQ(other.axis[k], in_order.axis[i]) << "bond " << i;
    EXPECT_EQ(other.end_force_alpha[k], in_order.end_force_alpha[i]) << "bond " << i;
    EXPECT_EQ(other.end_moment_alpha[k], in_order.end_moment_alpha[i]) << "bond " << i;
    EXPECT_EQ(other.end_moment_beta[k], in_order.end_moment_beta[i]) << "bond " << i;
  }
}

}  // namespace
}  // namespace bpm
