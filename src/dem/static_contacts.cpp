#include "dem/static_contacts.hpp"

#include <algorithm>

#include "contacts/neighbour_list.hpp"

namespace bpm {

std::vector<StaticContact> list_static_contacts(const Model& model, double gap) {
  std::vector<StaticContact> out;
  const ParticleStore& p = model.particles;
  if (!model.contacts.active() || p.size() < 2) return out;
  const ContactTable table(model.contacts);

  // Intact bond partners of each particle, sorted (CSR), for the bonded-pair rule. Built here so
  // that a model whose bonds are not finalised is read the same way.
  const BondStore& b = model.bonds;
  std::vector<std::int32_t> start(p.size() + 1, 0), partner(2 * b.size());
  auto intact = [&](std::size_t k) { return k >= b.intact.size() || b.intact[k] != 0; };
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!intact(k)) continue;
    ++start[static_cast<std::size_t>(b.alpha[k]) + 1];
    ++start[static_cast<std::size_t>(b.beta[k]) + 1];
  }
  for (std::size_t i = 0; i < p.size(); ++i) start[i + 1] += start[i];
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!intact(k)) continue;
    partner[static_cast<std::size_t>(fill[static_cast<std::size_t>(b.alpha[k])]++)] = b.beta[k];
    partner[static_cast<std::size_t>(fill[static_cast<std::size_t>(b.beta[k])]++)] = b.alpha[k];
  }
  for (std::size_t i = 0; i < p.size(); ++i) std::sort(partner.begin() + start[i], partner.begin() + start[i + 1]);
  auto bonded = [&](std::int32_t i, std::int32_t j) {
    const auto first = partner.begin() + start[static_cast<std::size_t>(i)];
    const auto last = partner.begin() + start[static_cast<std::size_t>(i) + 1];
    return std::binary_search(first, last, j);
  };

  NeighbourList list;
  list.build(p.position, p.radius, gap);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::int32_t i = list.first()[k], j = list.second()[k];
    const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
    const ContactPairParameters& params = table(p.material[si], p.material[sj]);
    if (!contact_law::contact_acts(params, bonded(i, j))) continue;
    const Vec3 d = p.position[sj] - p.position[si];
    const double distance = norm(d);
    if (!(distance > 0.0)) continue;  // coincident centres have no normal (the DEM reports them)
    out.push_back({i, j, d / distance, p.radius[si] + p.radius[sj] - distance, params,
                   {contact_rules::reduced(p.radius[si], p.radius[sj]), contact_rules::reduced(p.mass[si], p.mass[sj]),
                    contact_rules::reduced(p.inertia[si], p.inertia[sj])}});
  }
  return out;
}

}  // namespace bpm
