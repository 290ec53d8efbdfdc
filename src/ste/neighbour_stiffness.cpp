#include "ste/neighbour_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contacts/contact_law.hpp"
#include "statics/static_contact.hpp"
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
  // Overlapping pairs, with the bonded-pair rule (a vanishing gap lists every pair that may touch;
  // the overlap test keeps the touching ones), as springs of the law linearised at their overlap.
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  struct Pair {
    std::int32_t i, j;
    double k_n, k_t;
  };
  std::vector<Pair> pairs;
  for (const StaticContact& c : list_static_contacts(model, 1e-9 * r_max)) {
    if (!(c.overlap > 0.0)) continue;
    const contact_law::Linearised s = contact_law::linearise(c.params, c.inertia, c.overlap);
    pairs.push_back({c.i, c.j, s.normal_tangent, s.tangential});
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
