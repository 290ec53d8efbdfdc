#include "contacts/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace bpm {
namespace {
/// Centres closer than this fraction of the smaller radius count as coincident: a duplicated row
/// of a particles file, or two positions that differ only beyond the digits written.
constexpr double kCoincidentFraction = 1e-6;
}  // namespace

ContactForces::ContactForces(const ContactTable& table, const ParticleStore& particles, double skin)
    : table_(table), skin_(skin) {
  double r_max = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    r_max = std::max(r_max, particles.radius[i]);
    if (particles.material[i] < 0 || particles.material[i] >= table.size()) {
      throw InputError("particle " + std::to_string(particles.id[i]),
                       "material " + std::to_string(particles.material[i]) + " has no contact constants",
                       "give one contact material per particle material");
    }
  }
  if (!(skin_ > 0.0)) skin_ = 0.1 * r_max;
}

bool ContactForces::update_list(const ParticleStore& particles, const BondStore& bonds) {
  if (!list_.needs_rebuild(particles.position)) return false;
  const std::vector<std::int32_t> old_start = list_.row_start();
  const std::vector<std::int32_t> old_second = list_.second();
  const std::vector<Vec3> old_spring = spring_;
  list_.build(particles.position, particles.radius, skin_);

  const std::size_t pairs = list_.size();
  const std::vector<std::int32_t>& start = list_.row_start();
  const std::vector<std::int32_t>& first = list_.first();
  const std::vector<std::int32_t>& second = list_.second();
  spring_.assign(pairs, {});
  force_i_.assign(pairs, {});
  torque_i_.assign(pairs, {});
  torque_j_.assign(pairs, {});
  normal_force_.assign(pairs, 0.0);
  overlap_.assign(pairs, 0.0);

  const auto n = static_cast<std::int64_t>(particles.size());
  const bool carry = old_start.size() == start.size();
  // On the first build, the lowest pair whose centres coincide: its contact normal is undefined
  // (NaN forces in the first step, reported as a divergence).
  const bool check_centres = list_.builds() == 1;
  const auto row = [&](std::int64_t i) {
    auto lowest = static_cast<std::int64_t>(pairs);
    if (check_centres) {
      for (std::int32_t k = start[i]; k < start[i + 1]; ++k) {
        const std::int32_t j = second[k];
        const double r_min = std::min(particles.radius[i], particles.radius[j]);
        if (!(norm(particles.position[j] - particles.position[i]) > kCoincidentFraction * r_min)) {
          lowest = std::min<std::int64_t>(lowest, k);
        }
      }
    }
    // Both rows are sorted by j: a merge carries the springs of pairs listed before and now.
    if (carry) {
      std::int32_t o = old_start[i];
      for (std::int32_t k = start[i]; k < start[i + 1]; ++k) {
        while (o < old_start[i + 1] && old_second[o] < second[k]) ++o;
        if (o < old_start[i + 1] && old_second[o] == second[k]) spring_[k] = old_spring[o];
      }
    }
    return lowest;
  };
  const std::int64_t coincident = parallel_reduce(n, static_cast<std::int64_t>(pairs), row,
                                                  [](std::int64_t a, std::int64_t b) { return std::min(a, b); });

  if (coincident < static_cast<std::int64_t>(pairs)) {
    const auto k = static_cast<std::size_t>(coincident);
    const auto i = static_cast<std::size_t>(first[k]), j = static_cast<std::size_t>(second[k]);
    char what[256];
    std::snprintf(what, sizeof what,
                  "particles %lld and %lld are at the same centre (%.3g m apart, radii %.3g and %.3g m): their "
                  "contact has no direction",
                  static_cast<long long>(particles.id[i]), static_cast<long long>(particles.id[j]),
                  norm(particles.position[j] - particles.position[i]), particles.radius[i], particles.radius[j]);
    throw InputError("particles", what, "remove the duplicate particle or move it");
  }

  link_pairs(particles, bonds);
  return true;
}

void ContactForces::link_pairs(const ParticleStore& particles, const BondStore& bonds) {
  const std::size_t pairs = list_.size();
  const std::vector<std::int32_t>& start = list_.row_start();
  const std::vector<std::int32_t>& first = list_.first();
  const std::vector<std::int32_t>& second = list_.second();
  bond_.assign(pairs, -1);
  if (bonds.adjacency_start.size() == particles.size() + 1) {
    const auto n = static_cast<std::int64_t>(particles.size());
    parallel_for(n, [&](std::int64_t i) {
      for (std::int32_t k = start[i]; k < start[i + 1]; ++k) {
        for (std::int32_t e = bonds.adjacency_start[i]; e < bonds.adjacency_start[i + 1]; ++e) {
          const std::int32_t b = bonds.adjacency[e] >> 1;
          const std::int32_t other = (bonds.adjacency[e] & 1) == 0 ? bonds.beta[b] : bonds.alpha[b];
          if (other == second[k]) {
            bond_[k] = b;
            break;
          }
        }
      }
    });
  }

  pair_material_.resize(pairs);
  pair_inertia_.resize(pairs);
  pair_dashpots_.resize(pairs);
  parallel_for(static_cast<std::int64_t>(pairs), [&](std::int64_t k) {
    const std::int32_t i = first[k], j = second[k];
    pair_material_[k] = table_.index(particles.material[i], particles.material[j]);
    const ContactPairParameters& c = table_[pair_material_[k]];
    pair_inertia_[k] = inertia(particles, i, j, c);
    pair_dashpots_[k] = contact_law::dashpots(c, pair_inertia_[k]);
  });

  // Particle -> pairs adjacency, filled in pair order so each row is sorted.
  adjacency_start_.assign(particles.size() + 1, 0);
  for (std::size_t k = 0; k < pairs; ++k) {
    ++adjacency_start_[first[k] + 1];
    ++adjacency_start_[second[k] + 1];
  }
  for (std::size_t p = 0; p < particles.size(); ++p) adjacency_start_[p + 1] += adjacency_start_[p];
  std::vector<std::int32_t> fill(adjacency_start_.begin(), adjacency_start_.end() - 1);
  adjacency_.resize(2 * pairs);
  for (std::size_t k = 0; k < pairs; ++k) {
    adjacency_[fill[first[k]]++] = static_cast<std::int32_t>(2 * k);
    adjacency_[fill[second[k]]++] = static_cast<std::int32_t>(2 * k + 1);
  }
}

ContactForces::History ContactForces::history() const {
  return {list_.state(), spring_, force_i_, torque_i_, torque_j_, normal_force_, overlap_};
}

void ContactForces::restore(History history, const ParticleStore& particles, const BondStore& bonds) {
  list_.restore(std::move(history.list));
  spring_ = std::move(history.spring);
  force_i_ = std::move(history.force_i);
  torque_i_ = std::move(history.torque_i);
  torque_j_ = std::move(history.torque_j);
  normal_force_ = std::move(history.normal_force);
  overlap_ = std::move(history.overlap);
  link_pairs(particles, bonds);
}

contact_law::PairInertia ContactForces::inertia(const ParticleStore& p, std::int32_t i, std::int32_t j,
                                                const ContactPairParameters& c) const {
  // I* enters only the rolling friction (contact_law.hpp): not computed without it.
  return {contact_rules::reduced(p.radius[i], p.radius[j]), contact_rules::reduced(p.mass[i], p.mass[j]),
          c.rolling_friction > 0.0 ? contact_rules::reduced(p.inertia[i], p.inertia[j]) : 0.0};
}

bool ContactForces::switched_off(const BondStore& bonds, std::size_t pair, const ContactPairParameters& c) const {
  // The bond is read only where its state can matter: a contact that acts even beside an intact
  // bond (superimposed) saves one random access into the bond flags. Bonds without the flag (never
  // finalised) count as intact.
  if (contact_law::contact_acts(c, /*intact_bond_between=*/true) || bond_[pair] < 0) return false;
  const auto b = static_cast<std::size_t>(bond_[pair]);
  const bool intact = b >= bonds.intact.size() || bonds.intact[b] != 0;
  return !contact_law::contact_acts(c, intact);
}

void ContactForces::compute(const ParticleStore& particles, const BondStore& bonds, double increment_dt, double dt) {
  const auto pairs = static_cast<std::int64_t>(list_.size());
  const std::vector<std::int32_t>& first = list_.first();
  const std::vector<std::int32_t>& second = list_.second();
  const Vec3* x = particles.position.data();
  const Vec3* v = particles.velocity.data();
  const Vec3* w = particles.angular_velocity.data();
  const double* r = particles.radius.data();
  // Squared centre distances above reach^2 (1 + kApart) are certainly apart: the square root of such
  // a distance exceeds reach by far more than its rounding, so the overlap computed below would not
  // be positive either. Those pairs skip the square root; the same pairs count as touching as when
  // every pair took it.
  constexpr double kApart = 1e-12;
  // Partner j's rows are the loop's scattered loads (perf annotate: the most samples were on x[j]
  // and v[j]); they are asked for this many pairs ahead. 8, 16 and 32 measured alike.
  constexpr std::int64_t kPrefetchAhead = 16;
  parallel_for(pairs, [&](std::int64_t k) {
    if (k + kPrefetchAhead < pairs) {
      const std::int32_t ahead = second[k + kPrefetchAhead];
      __builtin_prefetch(&x[ahead]);
      __builtin_prefetch(&v[ahead]);
      __builtin_prefetch(&w[ahead]);
    }
    const std::int32_t i = first[k], j = second[k];
    const ContactPairParameters& c = table_[pair_material_[k]];
    const Vec3 d = x[j] - x[i];
    const double reach = r[i] + r[j];
    const double d2 = norm2(d);
    const bool apart = d2 > reach * reach * (1.0 + kApart);
    const double distance = apart ? 0.0 : std::sqrt(d2);
    const double overlap = reach - distance;
    if (apart || !(overlap > 0.0) || switched_off(bonds, static_cast<std::size_t>(k), c)) {
      // Not touching (or replaced by an intact bond): no load, and the tangential spring is lost.
      // A pair that was already in that state is left alone (no stores: most pairs stay apart).
      if (overlap_[k] != 0.0 || !all_bits_zero(spring_[k])) {
        spring_[k] = {};
        force_i_[k] = {};
        torque_i_[k] = {};
        torque_j_[k] = {};
        normal_force_[k] = 0.0;
        overlap_[k] = 0.0;
      }
      return;
    }
    const Vec3 n = d * (1.0 / distance);
    // Contact point in the middle of the overlap: arms R - delta/2 from each centre.
    const double a_i = r[i] - 0.5 * overlap, a_j = r[j] - 0.5 * overlap;
    const Vec3 v_rel = (v[j] - a_j * cross(w[j], n)) - (v[i] + a_i * cross(w[i], n));
    const contact_law::ContactLoad load = contact_law::evaluate(
        c, pair_inertia_[k], pair_dashpots_[k], {n, overlap, v_rel, w[i] - w[j]}, spring_[k], increment_dt, dt);
    const Vec3 n_x_f = cross(n, load.force);
    force_i_[k] = load.force;
    torque_i_[k] = a_i * n_x_f + load.rolling_torque;
    torque_j_[k] = a_j * n_x_f - load.rolling_torque;
    normal_force_[k] = load.normal_force;
    overlap_[k] = overlap;
  });
}

void ContactForces::gather(ParticleStore& particles) const {
  const auto n = static_cast<std::int64_t>(particles.size());
  if (!gathered(particles.size())) return;
  parallel_for(n, [&](std::int64_t p) {
    Vec3 force, torque;
    sum_loads(p, force, torque);
    particles.force[p] += force;
    particles.torque[p] += torque;
  });
}

double ContactForces::elastic_energy() const {
  double energy = 0.0;
  for (std::size_t k = 0; k < list_.size(); ++k) {
    if (!(overlap_[k] > 0.0)) continue;
    energy += contact_law::elastic_energy(table_[pair_material_[k]], pair_inertia_[k], overlap_[k], spring_[k]);
  }
  return energy;
}

std::int64_t ContactForces::touching() const {
  return std::count_if(overlap_.begin(), overlap_.end(), [](double o) { return o > 0.0; });
}

}  // namespace bpm
