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
  // Each row's share of one bond's element, for its 12 rows (a fixed DOF's row is skipped when
  // summed). sqrt(m_r m_c) takes 16 values, by the end and kind (mass, inertia) of either DOF: the
  // same products as one per entry, so the same sums bit for bit, at an eighth of the roots.
  auto row_shares = [&](const ElementMatrix& A, std::size_t bond, double* share) {
    const std::int32_t ends[2] = {b.alpha[bond], b.beta[bond]};
    auto kind = [](int dof) { return 2 * (dof / 6) + (dof % 6 < 3 ? 0 : 1); };
    double mass[4], root[4][4];
    for (int q = 0; q < 4; ++q) mass[q] = dof_mass(ends[q / 2], q % 2 == 0 ? 0 : 3);
    for (int q = 0; q < 4; ++q) {
      for (int s = 0; s < 4; ++s) root[q][s] = std::sqrt(mass[q] * mass[s]);
    }
    bool free[12];
    for (int r = 0; r < 12; ++r) free[r] = dof_free(ends[r / 6], r % 6);
    for (int r = 0; r < 12; ++r) {
      share[r] = 0.0;
      if (!free[r]) continue;
      // The quotients first (they vectorise), then summed in column order. A fixed column adds
      // +0.0, which leaves the sum (never -0.0: it starts at +0.0, the terms are >= 0) as it was.
      double term[12];
      for (int c = 0; c < 12; ++c)
        term[c] = free[c] ? std::abs(A(r, c)) / root[kind(r)][kind(c)] : 0.0;
      for (int c = 0; c < 12; ++c) share[r] += term[c];
    }
  };
  auto add_rows = [&](const double* share, std::size_t bond, std::vector<double>& sum, bool track) {
    const std::int32_t ends[2] = {b.alpha[bond], b.beta[bond]};
    for (int r = 0; r < 12; ++r) {
      const std::int32_t pr = ends[r / 6];
      if (!dof_free(pr, r % 6)) continue;
      const std::size_t row = 6 * static_cast<std::size_t>(pr) + static_cast<std::size_t>(r % 6);
      sum[row] += share[r];
      if (track && share[r] > stiffness_top[row]) {
        stiffness_top[row] = share[r];
        top_bond[row] = static_cast<std::int64_t>(bond);
      }
    }
  };
  const bool bond_damping = model.damping.bond > 0.0;
  // The elements (most of the cost) in parallel, a block of bonds at a time; their shares summed in
  // bond order, as one thread would, so the limit does not depend on the thread count.
  constexpr std::size_t kBlock = std::size_t{1} << 15;
  std::vector<double> shares(12 * kBlock), damping_shares(bond_damping ? 12 * kBlock : 0);
  for (std::size_t first = 0; first < b.size(); first += kBlock) {
    const auto count = static_cast<std::int64_t>(std::min(kBlock, b.size() - first));
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < count; ++k) {
      const std::size_t i = first + static_cast<std::size_t>(k);
      row_shares(bond_element_stiffness(p, b, i), i, &shares[12 * static_cast<std::size_t>(k)]);
      if (bond_damping) {
        const Vec3 d = p.position[b.beta[i]] - p.position[b.alpha[i]];
        const double length = norm(d);
        const BondStiffness dashpots{b.damping_force[i], b.damping_force[i], b.damping_moment[i],
                                     b.damping_moment[i]};
        row_shares(bond_element_stiffness(dashpots, d / length,
                                          bond_law::contact_arms(length, b.arm_offset[i])),
                   i, &damping_shares[12 * static_cast<std::size_t>(k)]);
      }
    }
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
      add_rows(&shares[12 * k], first + k, stiffness_sum, true);
      if (bond_damping) add_rows(&damping_shares[12 * k], first + k, damping_sum, false);
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
