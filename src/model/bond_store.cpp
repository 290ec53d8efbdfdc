#include "model/bond_store.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/error.hpp"
#include "model/particle_store.hpp"
#include "model/spatial_order.hpp"

namespace bpm {

void BondStore::add(std::int32_t a, std::int32_t b, const BondConstants& constants, double bond_radius,
                    double length, std::int32_t mat) {
  input_row.push_back(static_cast<std::int32_t>(alpha.size()));
  alpha.push_back(a);
  beta.push_back(b);
  stiffness.push_back(constants.stiffness);
  arm_offset.push_back(constants.arm_offset);
  radius.push_back(bond_radius);
  rest_length.push_back(length);
  material.push_back(mat);
  strength.push_back({});
}

void BondStore::reorder(const std::vector<std::int32_t>& old_at) {
  BPM_ASSERT(old_at.size() == size() && adjacency_start.empty() && breaks.empty());
  // Every per-bond field: a field left out here would silently belong to other bonds. The state
  // fields are empty before finalize() and permute() leaves them so.
  for (auto* field : {&alpha, &beta, &input_row, &material}) permute(*field, old_at);
  permute(stiffness, old_at);
  for (auto* field : {&arm_offset, &radius, &rest_length, &damping_force, &damping_moment}) {
    permute(*field, old_at);
  }
  permute(strength, old_at);
  for (auto* field : {&intact, &break_mode}) permute(*field, old_at);
  for (auto* field :
       {&force, &moment, &axis, &end_force_alpha, &end_moment_alpha, &end_moment_beta}) {
    permute(*field, old_at);
  }
}

void BondStore::draw_strengths(const std::vector<BondMaterial>& materials, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (std::size_t i = 0; i < size(); ++i) {
    const BondMaterial& m = materials.at(static_cast<std::size_t>(material[i]));
    const double area = std::numbers::pi * radius[i] * radius[i];  // A_b, Chen Eq. 23
    strength[i] = {m.tensile_strength.draw(rng) * area, m.shear_strength.draw(rng) * area};
  }
}

std::size_t BondStore::intact_count() const {
  return static_cast<std::size_t>(std::count(intact.begin(), intact.end(), std::uint8_t{1}));
}

void BondStore::finalize(const ParticleStore& particles, double eta_b) {
  const std::size_t n_bonds = size();
  intact.assign(n_bonds, 1);
  break_mode.assign(n_bonds, 0);
  strength.resize(n_bonds);
  breaks.clear();
  updates = 0;
  breakable = std::any_of(strength.begin(), strength.end(), [](const StrengthLimits& s) {
    return std::isfinite(s.tensile) || std::isfinite(s.shear);
  });
  force.assign(n_bonds, {});
  moment.assign(n_bonds, {});
  axis.resize(n_bonds);
  end_force_alpha.assign(n_bonds, {});
  end_moment_alpha.assign(n_bonds, {});
  end_moment_beta.assign(n_bonds, {});
  damping_force.resize(n_bonds);
  damping_moment.resize(n_bonds);
  for (std::size_t i = 0; i < n_bonds; ++i) {
    const Vec3 d = particles.position[beta[i]] - particles.position[alpha[i]];
    axis[i] = d / norm(d);
    const double m_a = particles.mass[alpha[i]], m_b = particles.mass[beta[i]];
    const double i_a = particles.inertia[alpha[i]], i_b = particles.inertia[beta[i]];
    const double m_bar = m_a * m_b / (m_a + m_b);  // reduced mass
    const double i_bar = i_a * i_b / (i_a + i_b);  // reduced moment of inertia
    damping_force[i] = 2.0 * eta_b * std::sqrt(stiffness[i].k_n * m_bar);  // Chen Eq. 9
    // Chen Eq. 10 as printed: sqrt(2 k_tor I_bar). The same coefficient acts on all three relative
    // rotation components, as Eq. 9's acts on all three translation components.
    damping_moment[i] = 2.0 * eta_b * std::sqrt(2.0 * stiffness[i].k_tor * i_bar);
  }

  const std::size_t n_particles = particles.size();
  adjacency_start.assign(n_particles + 1, 0);
  for (std::size_t i = 0; i < n_bonds; ++i) {
    ++adjacency_start[alpha[i] + 1];
    ++adjacency_start[beta[i] + 1];
  }
  for (std::size_t p = 0; p < n_particles; ++p) adjacency_start[p + 1] += adjacency_start[p];
  adjacency.resize(2 * n_bonds);
  std::vector<std::int32_t> fill(adjacency_start.begin(), adjacency_start.end() - 1);
  for (std::size_t i = 0; i < n_bonds; ++i) {
    const auto bond = static_cast<std::int32_t>(i);
    adjacency[fill[alpha[i]]++] = 2 * bond;
    adjacency[fill[beta[i]]++] = 2 * bond + 1;
  }
}

}  // namespace bpm
