#include "dem/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "linear/bond_element.hpp"

namespace bpm {

TimeStepLimit critical_time_step(const Model& model) {
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  // Per particle and DOF: mass (or inertia) and whether it is free.
  auto dof_mass = [&](std::int32_t particle, int local) {
    return local < 3 ? p.mass[particle] : p.inertia[particle];
  };
  auto dof_free = [&](std::int32_t particle, int local) {
    return local < 3 ? p.translation_free[particle][local] != 0.0
                     : p.rotation_free[particle][local - 3] != 0.0;
  };
  // Gershgorin row sums of M^-1/2 |A| M^-1/2 over the free DOFs, for the stiffness (A = K) and the
  // bond dashpots (A = C: the same element with {c_F, c_F, c_M, c_M} in place of the stiffness set,
  // since Chen Eq. 9-10 act on all three components of the relative motion).
  const std::size_t n_rows = 6 * p.size();
  std::vector<double> stiffness_sum(n_rows, 0.0), stiffness_top(n_rows, 0.0), damping_sum(n_rows, 0.0);
  std::vector<std::int64_t> top_bond(n_rows, -1);
  auto add_rows = [&](const ElementMatrix& A, std::size_t bond, std::vector<double>& sum, bool track) {
    const std::int32_t ends[2] = {b.alpha[bond], b.beta[bond]};
    for (int r = 0; r < 12; ++r) {
      const std::int32_t pr = ends[r / 6];
      if (!dof_free(pr, r % 6)) continue;
      double share = 0.0;
      for (int c = 0; c < 12; ++c) {
        const std::int32_t pc = ends[c / 6];
        if (!dof_free(pc, c % 6)) continue;
        share += std::abs(A(r, c)) / std::sqrt(dof_mass(pr, r % 6) * dof_mass(pc, c % 6));
      }
      const std::size_t row = 6 * static_cast<std::size_t>(pr) + static_cast<std::size_t>(r % 6);
      sum[row] += share;
      if (track && share > stiffness_top[row]) {
        stiffness_top[row] = share;
        top_bond[row] = static_cast<std::int64_t>(bond);
      }
    }
  };
  const bool bond_damping = model.damping.bond > 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    add_rows(bond_element_stiffness(p, b, i), i, stiffness_sum, true);
    if (bond_damping) {
      const Vec3 d = p.position[b.beta[i]] - p.position[b.alpha[i]];
      const double length = norm(d);
      const BondStiffness dashpots{b.damping_force[i], b.damping_force[i], b.damping_moment[i],
                                   b.damping_moment[i]};
      add_rows(bond_element_stiffness(dashpots, d / length, bond_law::contact_arms(length, b.arm_offset[i])),
               i, damping_sum, false);
    }
  }
  TimeStepLimit limit;
  double omega2 = 0.0;
  for (std::size_t row = 0; row < n_rows; ++row) {
    // Extreme but finite inputs (a density of 1e-200) overflow the bound to inf or NaN, which the
    // comparisons below would pass over as "no bond".
    if (!std::isfinite(stiffness_sum[row]) || !std::isfinite(damping_sum[row])) {
      const std::size_t particle = row / 6;
      char what[200];
      std::snprintf(what, sizeof what,
                    "cannot derive a stable time step: the frequency bound at particle %lld is not finite (mass %.3g kg)",
                    static_cast<long long>(p.id[particle]), p.mass[particle]);
      throw InputError("integrator.time_step", what,
                       "check the particle densities and radii and the bond Young's moduli for extreme values");
    }
    if (stiffness_sum[row] > omega2) {
      omega2 = stiffness_sum[row];
      limit.stiffest_bond = top_bond[row];
    }
  }
  if (omega2 <= 0.0) {
    throw InputError("integrator.time_step",
                     "cannot derive a stable time step: no bond acts on a free particle",
                     "set integrator.time_step explicitly");
  }
  limit.omega_max_bound = std::sqrt(omega2);
  // Local damping (Chen Eq. 11-12) adds up to gamma |F| along F when the velocity opposes the
  // load, i.e. acts like a stiffness of up to (1 + gamma) K.
  const double omega = limit.omega_max_bound * std::sqrt(1.0 + model.damping.particle);
  // Verlet with the dashpot force taken from the half-step velocity is stable for
  // (omega dt)^2 + 2 c dt <= 4 (one mode x'' + c x' + omega^2 x = 0); c bounds the eigenvalues of
  // M^-1/2 C M^-1/2 from above, as omega those of K. Solved for dt:
  const double c = *std::max_element(damping_sum.begin(), damping_sum.end());
  limit.critical = 4.0 / (c + std::sqrt(c * c + 4.0 * omega * omega));
  return limit;
}

}  // namespace bpm
