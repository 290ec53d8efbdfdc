#include "ste/neighbour_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contacts/contact_law.hpp"
#include "contacts/neighbour_list.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "linear/bond_element.hpp"

namespace bpm::ste {

NeighbourStiffness::NeighbourStiffness(const Model& model, bool include_contacts)
    : x_(model.particles.position.data()), bonds_(model.bonds), particles_(model.particles.size()) {
  const BondStore& b = model.bonds;
  check_intact_ = b.intact.size() == b.size();
  intact_bonds_ = check_intact_ ? b.size() - static_cast<std::size_t>(std::count(b.intact.begin(), b.intact.end(), 0))
                                : b.size();
  if (b.adjacency_start.size() == particles_ + 1 && b.adjacency.size() == 2 * b.size()) {
    bond_start_ = b.adjacency_start.data();
    bond_adjacency_ = b.adjacency.data();
  } else {
    // Not finalised: the same CSR layout as BondStore::finalize, built here.
    own_start_.assign(particles_ + 1, 0);
    for (std::size_t i = 0; i < b.size(); ++i) {
      ++own_start_[static_cast<std::size_t>(b.alpha[i]) + 1];
      ++own_start_[static_cast<std::size_t>(b.beta[i]) + 1];
    }
    for (std::size_t p = 0; p < particles_; ++p) own_start_[p + 1] += own_start_[p];
    own_adjacency_.resize(2 * b.size());
    std::vector<std::int32_t> fill(own_start_.begin(), own_start_.end() - 1);
    for (std::size_t i = 0; i < b.size(); ++i) {
      const auto bond = static_cast<std::int32_t>(i);
      own_adjacency_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b.alpha[i])]++)] = 2 * bond;
      own_adjacency_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b.beta[i])]++)] = 2 * bond + 1;
    }
    bond_start_ = own_start_.data();
    bond_adjacency_ = own_adjacency_.data();
  }
  // K^nm of every intact bond, once: the unified bond law's translational block about the current
  // axis (the same from either end: R^T diag(k_n, k_s, k_s) R does not change when n flips).
  bond_k_.assign(b.size(), SymmetricK{0.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  const auto n_bonds = static_cast<std::int64_t>(b.size());
#pragma omp parallel for schedule(static) if (n_bonds >= kParallelMinItems)
  for (std::int64_t i = 0; i < n_bonds; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (check_intact_ && b.intact[k] == 0) continue;
    const Vec3 d = x_[static_cast<std::size_t>(b.beta[k])] - x_[static_cast<std::size_t>(b.alpha[k])];
    const Eigen::Matrix3d K = bond_translational_stiffness(b.stiffness[k], d / norm(d));
    bond_k_[k] = {K(0, 0), K(1, 1), K(2, 2), K(1, 2), K(0, 2), K(0, 1)};
  }
  contact_start_.assign(particles_ + 1, 0);
  if (include_contacts && particles_ > 1) build_contacts(model);
}

void NeighbourStiffness::build_contacts(const Model& model) {
  const ParticleStore& p = model.particles;
  const ContactTable table(model.contacts);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.material[i] < 0 || p.material[i] >= table.size()) {
      throw InputError("stiffness tensor estimation: particle " + std::to_string(p.id[i]),
                       "has material " + std::to_string(p.material[i]) + " without contact constants",
                       "give a contact material for every particle material or set include_contacts off");
    }
  }
  // Overlapping pairs: the contact neighbour list with a vanishing skin lists every pair with a
  // gap below it; the overlap test below keeps the touching ones.
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  NeighbourList list;
  list.build(p.position, p.radius, 1e-9 * r_max);

  struct Pair {
    std::int32_t i, j;
    double k_n, k_t;
  };
  std::vector<Pair> pairs;
  const std::vector<std::int32_t>& first = list.first();
  const std::vector<std::int32_t>& second = list.second();
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::int32_t i = first[k], j = second[k];
    const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
    const double distance = norm(p.position[sj] - p.position[si]);
    const double overlap = p.radius[si] + p.radius[sj] - distance;
    if (!(overlap > 0.0)) continue;
    const ContactPairParameters& c = table(p.material[si], p.material[sj]);
    if (c.bonded == BondedContacts::replace) {
      bool bonded = false;  // an intact bond between i and j switches the contact off
      for (std::int32_t e = bond_start_[si]; e < bond_start_[si + 1] && !bonded; ++e) {
        const std::int32_t entry = bond_adjacency_[static_cast<std::size_t>(e)];
        const auto b = static_cast<std::size_t>(entry >> 1);
        const std::int32_t other = (entry & 1) == 0 ? bonds_.beta[b] : bonds_.alpha[b];
        bonded = other == j && (!check_intact_ || bonds_.intact[b] != 0);
      }
      if (bonded) continue;
    }
    const contact_law::PairInertia g{contact_rules::reduced(p.radius[si], p.radius[sj]),
                                     contact_rules::reduced(p.mass[si], p.mass[sj]),
                                     contact_rules::reduced(p.inertia[si], p.inertia[sj])};
    const contact_law::Stiffness s = contact_law::stiffness(c, g, overlap);
    // Tangent normal stiffness dF_n/d delta: Hertz 2 E* sqrt(R* delta) (= 3/2 F_n / delta).
    const double k_n = c.law == ContactLaw::hertz_mindlin ? 2.0 * c.e_star * std::sqrt(g.r_star * overlap) : c.k_n;
    pairs.push_back({i, j, k_n, s.k_t});
  }
  // Per-particle CSR, each pair seen from both ends, in pair order.
  for (const Pair& c : pairs) {
    ++contact_start_[static_cast<std::size_t>(c.i) + 1];
    ++contact_start_[static_cast<std::size_t>(c.j) + 1];
  }
  for (std::size_t n = 0; n < particles_; ++n) contact_start_[n + 1] += contact_start_[n];
  springs_.resize(2 * pairs.size());
  std::vector<std::size_t> fill(contact_start_.begin(), contact_start_.end() - 1);
  for (const Pair& c : pairs) {
    springs_[fill[static_cast<std::size_t>(c.i)]++] = {c.j, c.k_n, c.k_t};
    springs_[fill[static_cast<std::size_t>(c.j)]++] = {c.i, c.k_n, c.k_t};
  }
}

}  // namespace bpm::ste
