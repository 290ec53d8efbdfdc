// The contact loop (ContactForces::compute and gather) against a plain reference loop written from
// the contact law alone: every listed pair evaluated with contact_law::evaluate, bond rules checked
// from the bond list, and the loads summed per particle in pair order with a branch on the side.
// The optimised loop (apart pairs without a square root, no stores for pairs that stay apart, I*
// only with rolling friction, a branch-free gather) must find the same pairs in contact, store
// exact zeros for the others, agree with the plain formulas to 1e-12 of the load (not bit for bit: the
// compiler fuses multiply-adds differently in the two loops) and gather bit for bit, over
// steps in which pairs come into contact and separate, with and without rolling friction, and
// bonded pairs that superimpose or replace (bond intact or broken) their contact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "../dem/dem_helpers.hpp"
#include "contact_helpers.hpp"
#include "contacts/contact_forces.hpp"

namespace bpm {
namespace {

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

struct Cluster {
  Model model;
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> bond_of;  ///< (i < j) -> bond
};

/// 8 x 8 x 8 spheres (radius 0.9-1.1 mm) on a 2 mm lattice, jittered: many overlaps and many gaps.
/// Materials: 0 Hertz-Mindlin with rolling friction, 1 without; pairs of 0 and 1 replace their
/// contact by a bond and have no rolling friction. Every third lattice neighbour pair bonded, every
/// fifth bond broken.
Cluster cluster() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Cluster c;
  Model& m = c.model;
  constexpr int kSide = 8;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      for (int k = 0; k < kSide; ++k) {
        const Vec3 x{2e-3 * i + 1e-4 * u(rng), 2e-3 * j + 1e-4 * u(rng), 2e-3 * k + 1e-4 * u(rng)};
        const std::int32_t p = m.particles.add((i * kSide + j) * kSide + k, x, 1e-3 + 1e-4 * u(rng), 2500.0,
                                               (i + j + k) % 3 == 0 ? 1 : 0);
        m.particles.velocity[p] = {0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)};
        m.particles.angular_velocity[p] = {100.0 * u(rng), 100.0 * u(rng), 100.0 * u(rng)};
      }
    }
  }
  int neighbours = 0;
  for (std::int32_t a = 0; a < static_cast<std::int32_t>(m.particles.size()); ++a) {
    for (std::int32_t b = a + 1; b < static_cast<std::int32_t>(m.particles.size()); ++b) {
      if (norm(m.particles.position[b] - m.particles.position[a]) < 2.3e-3 && neighbours++ % 3 == 0) {
        c.bond_of[{a, b}] = static_cast<std::int32_t>(m.bonds.size());
        test::bond(m, a, b, test::steel_bond("tbbm"));
      }
    }
  }
  m.contacts.particle_particle = true;
  m.contacts.materials = {test::hertz_material(1e8, 0.3, 0.5, 0.3, 0.05), test::hertz_material(3e8, 0.25, 0.7, 0.4)};
  ContactPairRule rule;
  rule.a = 0;
  rule.b = 1;
  rule.rolling_friction = 0.0;
  rule.bonded = BondedContacts::replace;
  m.contacts.pair_rules = {rule};
  m.contacts.skin = 1e-3;  // wide: the list is built once and holds every pair that touches below
  m.finalize();
  for (std::size_t b = 0; b < m.bonds.size(); b += 5) m.bonds.intact[b] = 0;
  return c;
}

TEST(ContactReferenceLoopTest, OptimisedLoopMatchesThePlainLoop) {
  Cluster c = cluster();
  Model& m = c.model;
  ParticleStore& p = m.particles;
  const ContactTable table(m.contacts);
  ContactForces contacts(table, p, m.contacts.skin);
  ASSERT_TRUE(contacts.update_list(p, m.bonds));
  const NeighbourList& list = contacts.list();
  const std::size_t pairs = list.size();
  ASSERT_GT(pairs, 1000u);

  std::vector<Vec3> spring(pairs), force(pairs), torque_i(pairs), torque_j(pairs);
  std::vector<double> normal(pairs);
  constexpr double kDt = 1e-6;
  constexpr double kClose = 1e-12;  // relative
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::int64_t touching = 0, apart = 0, replaced = 0, changed = 0;
  std::vector<bool> was_touching(pairs, false);
  for (int step = 0; step < 12; ++step) {
    contacts.compute(p, m.bonds, kDt, kDt);
    for (std::size_t k = 0; k < pairs; ++k) {
      const std::int32_t i = list.first()[k], j = list.second()[k];
      const ContactPairParameters& cp = table(p.material[i], p.material[j]);
      const Vec3 d = p.position[j] - p.position[i];
      const double distance = norm(d);
      const double overlap = p.radius[i] + p.radius[j] - distance;
      const auto bond = c.bond_of.find({i, j});
      const bool intact = bond != c.bond_of.end() && m.bonds.intact[bond->second] != 0;
      const bool acts = overlap > 0.0 && contact_law::contact_acts(cp, intact);
      if (overlap > 0.0 && !acts) ++replaced;
      if (step > 0 && acts != was_touching[k]) ++changed;
      was_touching[k] = acts;
      if (!acts) {
        ++apart;
        spring[k] = force[k] = torque_i[k] = torque_j[k] = {};
        normal[k] = 0.0;
      } else {
        ++touching;
        const Vec3 n = d * (1.0 / distance);
        const double a_i = p.radius[i] - 0.5 * overlap, a_j = p.radius[j] - 0.5 * overlap;
        const Vec3 v_rel = (p.velocity[j] - a_j * cross(p.angular_velocity[j], n)) -
                           (p.velocity[i] + a_i * cross(p.angular_velocity[i], n));
        const contact_law::PairInertia g{contact_rules::reduced(p.radius[i], p.radius[j]),
                                         contact_rules::reduced(p.mass[i], p.mass[j]),
                                         contact_rules::reduced(p.inertia[i], p.inertia[j])};
        const contact_law::ContactLoad load = contact_law::evaluate(
            cp, g, {n, overlap, v_rel, p.angular_velocity[i] - p.angular_velocity[j]}, spring[k], kDt, kDt);
        const Vec3 n_x_f = cross(n, load.force);
        force[k] = load.force;
        torque_i[k] = a_i * n_x_f + load.rolling_torque;
        torque_j[k] = a_j * n_x_f - load.rolling_torque;
        normal[k] = load.normal_force;
      }
      if (!acts) {  // exactly the state of a pair out of contact
        ASSERT_TRUE(same_bits(contacts.spring()[k], Vec3{})) << "step " << step << ", pair " << k;
        ASSERT_TRUE(same_bits(contacts.force()[k], Vec3{})) << "step " << step << ", pair " << k;
        ASSERT_TRUE(same_bits(contacts.torque_i()[k], Vec3{})) << "step " << step << ", pair " << k;
        ASSERT_TRUE(same_bits(contacts.torque_j()[k], Vec3{})) << "step " << step << ", pair " << k;
        ASSERT_TRUE(same_bits(contacts.normal_force()[k], 0.0)) << "step " << step << ", pair " << k;
      } else {  // the same formulas, up to the compiler's contractions into fused multiply-adds
        // Torques are a (n x F): near a normal force, n x F cancels down to the rounding of F.
        const double f = norm(force[k]), t = kClose * (norm(torque_i[k]) + 2.0 * p.radius[i] * f);
        EXPECT_NEAR(norm(contacts.spring()[k] - spring[k]), 0.0, kClose * norm(spring[k]) + 1e-20) << "pair " << k;
        EXPECT_NEAR(norm(contacts.force()[k] - force[k]), 0.0, kClose * f) << "pair " << k;
        EXPECT_NEAR(norm(contacts.torque_i()[k] - torque_i[k]), 0.0, t) << "pair " << k;
        EXPECT_NEAR(norm(contacts.torque_j()[k] - torque_j[k]), 0.0, t + kClose * 2.0 * p.radius[j] * f)
            << "pair " << k;
        EXPECT_NEAR(contacts.normal_force()[k], normal[k], kClose * f) << "pair " << k;
      }
      spring[k] = contacts.spring()[k];  // both continue from the same spring
    }
    ASSERT_FALSE(HasFailure());

    // The gather: per particle, its pairs in pair order, j taking the opposite force (only
    // additions: the same bits).
    std::vector<Vec3> sum_f(p.size()), sum_t(p.size());
    for (std::size_t a = 0; a < p.size(); ++a) {
      for (std::size_t k = 0; k < pairs; ++k) {
        if (static_cast<std::size_t>(list.first()[k]) == a) {
          sum_f[a] += contacts.force()[k];
          sum_t[a] += contacts.torque_i()[k];
        } else if (static_cast<std::size_t>(list.second()[k]) == a) {
          sum_f[a] -= contacts.force()[k];
          sum_t[a] += contacts.torque_j()[k];
        }
      }
    }
    std::fill(p.force.begin(), p.force.end(), Vec3{});
    std::fill(p.torque.begin(), p.torque.end(), Vec3{});
    contacts.gather(p);
    for (std::size_t a = 0; a < p.size(); ++a) {
      ASSERT_TRUE(same_bits(p.force[a], sum_f[a])) << "step " << step << ", particle " << a;
      ASSERT_TRUE(same_bits(p.torque[a], sum_t[a])) << "step " << step << ", particle " << a;
    }

    // Move every particle a little (within the skin) so that pairs close and open.
    for (std::size_t a = 0; a < p.size(); ++a) {
      p.position[a] += Vec3{2e-5 * u(rng), 2e-5 * u(rng), 2e-5 * u(rng)};
      p.velocity[a] += Vec3{0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng)};
    }
  }
  EXPECT_FALSE(contacts.update_list(p, m.bonds));  // one list throughout
  // The cases the loop distinguishes all occurred.
  EXPECT_GT(touching, 1000);
  EXPECT_GT(apart, 1000);
  EXPECT_GT(replaced, 10);
  EXPECT_GT(changed, 50);
}

}  // namespace
}  // namespace bpm
