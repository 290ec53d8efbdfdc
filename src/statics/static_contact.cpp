#include "statics/static_contact.hpp"

#include <algorithm>

#include <Eigen/Dense>

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
  for (std::size_t i = 0; i < p.size(); ++i)
    std::sort(partner.begin() + start[i], partner.begin() + start[i + 1]);
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
    StaticContact c;
    c.i = i;
    c.j = j;
    c.n = d / distance;
    c.overlap = p.radius[si] + p.radius[sj] - distance;
    c.arm_i = p.radius[si] - 0.5 * c.overlap;
    c.arm_j = p.radius[sj] - 0.5 * c.overlap;
    c.params = params;
    c.inertia = {contact_rules::reduced(p.radius[si], p.radius[sj]),
                 contact_rules::reduced(p.mass[si], p.mass[sj]),
                 contact_rules::reduced(p.inertia[si], p.inertia[sj])};
    linearise_at(c, c.overlap);
    out.push_back(c);
  }
  return out;
}

StaticContact wall_contact(const Model& model, std::int32_t i, std::int32_t wall_material,
                           const Vec3& wall_normal, double gap, const Vec3& wall_motion) {
  const ParticleStore& p = model.particles;
  const auto si = static_cast<std::size_t>(i);
  StaticContact c;
  c.i = i;
  c.n = -1.0 * wall_normal;
  c.overlap = -gap;
  c.arm_i = p.radius[si] + 0.5 * gap;  // R - delta_0/2
  c.wall_motion = wall_motion;
  c.params = ContactTable(model.contacts)(p.material[si], wall_material);
  c.inertia = {p.radius[si], p.mass[si], p.inertia[si]};  // a rigid partner
  linearise_at(c, c.overlap);
  return c;
}

void linearise_at(StaticContact& c, double delta) {
  const contact_law::Linearised l = contact_law::linearise(c.params, c.inertia, delta);
  c.k_n = l.normal_tangent;
  // A frictionless contact carries no tangential force (the DEM caps it at mu F_n = 0).
  c.k_t = c.params.friction > 0.0 ? l.tangential : 0.0;
}

ElementMatrix contact_element_stiffness(const StaticContact& c, int dofs) {
  const Eigen::Vector3d n(c.n[0], c.n[1], c.n[2]);
  const Eigen::Matrix3d C =
      c.k_n * n * n.transpose() + c.k_t * (Eigen::Matrix3d::Identity() - n * n.transpose());
  ElementMatrix k = ElementMatrix::Zero();
  if (dofs == 3) {
    k.block<3, 3>(0, 0) = C;
    k.block<3, 3>(0, 3) = -C;
    k.block<3, 3>(3, 0) = -C;
    k.block<3, 3>(3, 3) = C;
    return k;
  }
  auto skew = [](const Eigen::Vector3d& v) {
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return s;
  };
  Eigen::Matrix<double, 3, 12> B;
  B << -Eigen::Matrix3d::Identity(), skew(c.arm_i * n), Eigen::Matrix3d::Identity(),
      skew(c.arm_j * n);
  k = B.transpose() * C * B;
  return k;
}

}  // namespace bpm
