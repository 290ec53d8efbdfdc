#include "dem/time_step.hpp"

#include <cmath>
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
  std::vector<double> row_sum(6 * p.size(), 0.0);
  std::vector<double> row_top_share(6 * p.size(), 0.0);
  std::vector<std::int64_t> row_top_bond(6 * p.size(), -1);
  for (std::size_t i = 0; i < b.size(); ++i) {
    const ElementMatrix K = bond_element_stiffness(p, b, i);
    const std::int32_t ends[2] = {b.alpha[i], b.beta[i]};
    for (int r = 0; r < 12; ++r) {
      const std::int32_t pr = ends[r / 6];
      if (!dof_free(pr, r % 6)) continue;
      double share = 0.0;
      for (int c = 0; c < 12; ++c) {
        const std::int32_t pc = ends[c / 6];
        if (!dof_free(pc, c % 6)) continue;
        share += std::abs(K(r, c)) / std::sqrt(dof_mass(pr, r % 6) * dof_mass(pc, c % 6));
      }
      const std::size_t row = 6 * static_cast<std::size_t>(pr) + static_cast<std::size_t>(r % 6);
      row_sum[row] += share;
      if (share > row_top_share[row]) {
        row_top_share[row] = share;
        row_top_bond[row] = static_cast<std::int64_t>(i);
      }
    }
  }
  TimeStepLimit limit;
  double omega2 = 0.0;
  for (std::size_t row = 0; row < row_sum.size(); ++row) {
    if (row_sum[row] > omega2) {
      omega2 = row_sum[row];
      limit.stiffest_bond = row_top_bond[row];
    }
  }
  if (omega2 <= 0.0) {
    throw InputError("integrator.time_step",
                     "cannot derive a stable time step: no bond acts on a free particle",
                     "set integrator.time_step explicitly");
  }
  limit.omega_max_bound = std::sqrt(omega2);
  const double zeta = std::sqrt(2.0) * model.damping.bond;
  // Local damping (Chen Eq. 11-12) adds up to gamma |F| along F when the velocity opposes the
  // load, i.e. acts like a stiffness of up to (1 + gamma) K.
  const double local = 1.0 / std::sqrt(1.0 + model.damping.particle);
  limit.critical = 2.0 / limit.omega_max_bound * (std::sqrt(1.0 + zeta * zeta) - zeta) * local;
  return limit;
}

}  // namespace bpm
