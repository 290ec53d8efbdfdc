// The static core (statics/static_problem.hpp) on a jittered bonded lattice between Hertz platens:
// its tangent is the derivative of the equilibrium platen force, the platens balance, slip with
// history at frictional platens can only soften the sample, down to the frictionless answer, and
// the bonds' current axes are a second-order term: it vanishes with the strain, linearly.
#include <gtest/gtest.h>

#include "dsm/dsm_helpers.hpp"
#include "dsm/dsm_linear.hpp"
#include "dsm/dsm_nonlinear.hpp"
#include "dsm/platen_constraints.hpp"
#include "dsm/platen_springs.hpp"
#include "statics/static_problem.hpp"

namespace bpm {
namespace {

constexpr double kRadius = 1e-3;

Model lattice(double platen_friction) {
  Model model = test::flat_ended_lattice(3, 3, 5, kRadius, 0.15, 21);
  for (ContactMaterial& m : model.contacts.materials) m.friction = platen_friction;
  return model;
}

TEST(StaticProblem, TangentIsTheDerivativeOfTheEquilibriumForce) {
  const Model model = lattice(0.0);
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(1e-3));
  const DofConstraints c = platen_constraints(model, load, 6, /*kinematic_platens=*/false);
  // The small-displacement problem: Newton's matrix leaves the bonds' turning out.
  StaticProblem problem(model, c, platen_contacts(model, load, c, load.displacement),
                        {6, {}, false, /*bond_axes=*/false});
  const double w = 0.6 * load.displacement, h = 1e-2 * w;
  auto force_at = [&](double travel) {
    problem.solve(travel, 1e-12, "test");
    return problem.wall_force(travel, true);
  };
  const double below = force_at(w - h), above = force_at(w + h);
  force_at(w);
  EXPECT_NEAR(problem.wall_force(w, true), problem.wall_force(w, false),
              1e-8 * problem.wall_force(w, true));
  Eigen::VectorXd v;
  const double tangent = problem.tangent_stiffness(w, 1e-12, v, {});
  EXPECT_NEAR(tangent, (above - below) / (2.0 * h), 1e-5 * tangent);
}

// A platen contact that slides adds no tangential stiffness to the DSM's loading tangent: with a
// friction that every platen contact exceeds, the DSM with walls is the frictionless one.
TEST(StaticProblem, SlidingPlatensGiveTheFrictionlessTangent) {
  auto stiffness = [](double friction) {
    Model model =
        test::flat_ended_lattice(3, 3, 5, kRadius, 0.5, 21);  // inclined bonds: it spreads
    for (ContactMaterial& m : model.contacts.materials) m.friction = friction;
    const PlatenLoading load = make_platen_loading(model, test::compression_along_z(1e-3));
    DsmOptions options;
    options.bond_axes = false;
    return solve_dsm_linear(model, load, options).stiffness;
  };
  const double frictionless = stiffness(0.0), slippery = stiffness(1e-4), stuck = stiffness(0.5);
  EXPECT_NEAR(slippery, frictionless, 1e-6 * frictionless);
  EXPECT_GT(stuck, (1.0 + 1e-4) * frictionless);
}

TEST(StaticProblem, PlatenSlipSoftensDownToTheFrictionlessAnswer) {
  auto stiffness = [](double friction, bool slip) {
    const Model model = lattice(friction);
    const PlatenLoading load = make_platen_loading(model, test::compression_along_z(1e-3));
    DsmOptions options;
    options.nonlinear_tolerance = 1e-8;
    options.slip = slip;
    return solve_dsm_nonlinear(model, load, options).stiffness;
  };
  const double frictionless = stiffness(0.0, true), stuck = stiffness(0.5, false),
               sliding = stiffness(0.5, true), slippery = stiffness(1e-3, true),
               huge = stiffness(1e6, true);
  EXPECT_GT(stuck, (1.0 + 1e-4) * frictionless);  // friction holds the ends against lateral spread
  EXPECT_LE(sliding, stuck * (1.0 + 1e-9));
  EXPECT_NEAR(huge, stuck, 1e-7 * stuck);  // a friction no contact reaches: no slip
  EXPECT_NEAR(slippery, frictionless, 2e-3 * frictionless);
  EXPECT_LT(slippery, sliding);
}

TEST(StaticProblem, BondAxesSoftenCompressionInProportionToTheStrain) {
  // Jittered by half a radius: inclined bonds, whose ends move apart sideways under compression.
  Model model = test::flat_ended_lattice(3, 3, 5, kRadius, 0.5, 21);
  for (ContactMaterial& m : model.contacts.materials) m.friction = 0.5;
  auto softening = [&](double strain) {
    const PlatenLoading load = make_platen_loading(model, test::compression_along_z(strain));
    DsmOptions options;
    options.nonlinear_tolerance = 1e-8;
    options.bond_axes = false;
    const double small = solve_dsm_nonlinear(model, load, options).stiffness;
    options.bond_axes = true;
    return solve_dsm_nonlinear(model, load, options).stiffness / small - 1.0;
  };
  const double at1 = softening(5e-3), at2 = softening(1e-2);
  EXPECT_LT(at1, -1e-6);  // compressed bonds give way sideways (P-delta)
  EXPECT_GT(at1, -1e-3);
  EXPECT_NEAR(at2 / at1, 2.0, 0.15);  // to leading order; the platens' Hertz law adds the rest
}

}  // namespace
}  // namespace bpm
