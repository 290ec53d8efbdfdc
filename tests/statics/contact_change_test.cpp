// ContactStiffnessChange (statics/contact_change.hpp) against the assembled matrices it replaces:
// on a jittered lattice with contacts at two linearisations and some DOFs held, (K(now) - K(start))
// x on the free rows, for 3 and 6 DOF per particle.
#include <gtest/gtest.h>

#include <random>

#include "dsm/dsm_helpers.hpp"
#include "statics/contact_change.hpp"
#include "statics/dof_constraints.hpp"
#include "statics/static_assembly.hpp"

namespace bpm {
namespace {

struct Linearisations {
  std::vector<StaticContact> start, now;
};

/// Every pair closer than 2.3 R, with random stiffnesses; some contacts open (zero) in one of them.
Linearisations random_contacts(const Model& model, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> k(1e5, 1e7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Linearisations out;
  const auto& x = model.particles.position;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      const double r = model.particles.radius[i];
      if (norm(x[j] - x[i]) > 2.3 * r) continue;
      StaticContact c;
      c.i = static_cast<std::int32_t>(i);
      c.j = static_cast<std::int32_t>(j);
      c.n = (x[j] - x[i]) / norm(x[j] - x[i]);
      c.arm_i = 0.97 * r;
      c.arm_j = 0.95 * r;
      c.k_n = k(rng);
      c.k_t = k(rng);
      StaticContact later = c;
      later.k_n = unit(rng) < 0.2 ? 0.0 : k(rng);
      later.k_t = later.k_n == 0.0 ? 0.0 : k(rng);
      if (unit(rng) < 0.1) c.k_n = c.k_t = 0.0;  // touches only later
      if (unit(rng) < 0.1) later = c;            // unchanged
      out.start.push_back(c);
      out.now.push_back(later);
    }
  }
  return out;
}

void expect_matches_assembly(int dofs) {
  const Model model = test::flat_ended_lattice(3, 3, 4, 1e-3, 0.05, 11);
  std::mt19937_64 rng(5);
  const Linearisations contacts = random_contacts(model, rng);
  ASSERT_GT(contacts.start.size(), 50u);
  const auto n = static_cast<Eigen::Index>(dofs * model.particles.size());
  DofConstraints held;
  held.dofs = dofs;
  held.fixed.assign(static_cast<std::size_t>(n), 0);
  held.value.assign(static_cast<std::size_t>(n), 0.0);
  for (Eigen::Index i = 0; i < n; i += 7) held.fixed[static_cast<std::size_t>(i)] = 1;
  SparseMatrixRM K0 = assemble_stiffness(model, dofs, contacts.start);
  SparseMatrixRM K1 = assemble_stiffness(model, dofs, contacts.now);
  Eigen::VectorXd unused = Eigen::VectorXd::Zero(n);
  apply_constraints(K0, unused, held);
  apply_constraints(K1, unused, held);

  const ContactStiffnessChange change(model.particles.size(), dofs, contacts.start, contacts.now,
                                      held.fixed);
  std::uniform_real_distribution<double> u(-1e-6, 1e-6);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) x[i] = u(rng);
  const Eigen::VectorXd expected = K1 * x - K0 * x;
  Eigen::VectorXd y = Eigen::VectorXd::Constant(n, 0.25);  // adds to what is there
  change.add_product(x.data(), y.data());
  double scale = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) scale = std::max(scale, std::abs(expected[i]));
  ASSERT_GT(scale, 0.0);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (held.fixed[static_cast<std::size_t>(i)]) {
      EXPECT_EQ(y[i], 0.25) << "held row " << i << " is left alone";
    } else {
      EXPECT_NEAR(y[i] - 0.25, expected[i], 1e-9 * scale) << "row " << i;
    }
  }
}

TEST(ContactStiffnessChange, MatchesTheAssembledDifferenceWithSixDofs) {
  expect_matches_assembly(6);
}

TEST(ContactStiffnessChange, MatchesTheAssembledDifferenceWithThreeDofs) {
  expect_matches_assembly(3);
}

TEST(ContactStiffnessChange, IsEmptyWhenNothingChanged) {
  const Model model = test::flat_ended_lattice(2, 2, 3, 1e-3, 0.0, 1);
  std::mt19937_64 rng(2);
  const Linearisations contacts = random_contacts(model, rng);
  const std::vector<std::uint8_t> free(6 * model.particles.size(), 0);
  EXPECT_TRUE(
      ContactStiffnessChange(model.particles.size(), 6, contacts.start, contacts.start, free)
          .empty());
}

}  // namespace
}  // namespace bpm
