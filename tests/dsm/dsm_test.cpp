// The direct stiffness method: assembly from the bond element, kinematic platens against the
// analytic columns-in-series stiffness and against the explicit DEM with the same constraints
// (particle by particle), touching contacts as linear elements, and the platen walls: the linear
// DSM's tangent at its operating point and the nonlinear variant's chord against the analytic
// series solution with Hertz platens.
#include <gtest/gtest.h>

#include <cmath>

#include "compress/kinematic_compression.hpp"
#include "core/error.hpp"
#include "statics/static_assembly.hpp"
#include "dsm/platen_constraints.hpp"
#include "linear/bond_element.hpp"
#include "dsm/dsm_helpers.hpp"
#include "dsm/dsm_linear.hpp"
#include "dsm/dsm_nonlinear.hpp"
#include "dsm/fit_window.hpp"
#include "dsm/platen_springs.hpp"
#include "statics/static_solver.hpp"

namespace bpm {
namespace {

using test::cubic_lattice;

constexpr double kRadius = 1e-3;

/// The sum of every intact bond's 12x12 element (linear/bond_element.hpp), dense: the assembly's
/// reference.
Eigen::MatrixXd dense_bond_sum(const Model& model) {
  const auto n = static_cast<Eigen::Index>(6 * model.particles.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  const BondStore& b = model.bonds;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b.intact[i]) continue;
    const ElementMatrix k = bond_element_stiffness(model.particles, b, i);
    const Eigen::Index ends[2] = {6 * static_cast<Eigen::Index>(b.alpha[i]), 6 * static_cast<Eigen::Index>(b.beta[i])};
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c) K.block<6, 6>(ends[r], ends[c]) += k.block<6, 6>(6 * r, 6 * c);
    }
  }
  return K;
}

TEST(DsmAssembly, SixDofMatrixIsTheSumOfTheIntactBondElements) {
  Model model = cubic_lattice(3, 3, 4, kRadius, 0.2, 0.0, 0.0, 7);
  model.bonds.intact[3] = 0;  // a broken bond carries nothing
  const SparseMatrixRM K = assemble_bond_stiffness(model, 6);
  const Eigen::MatrixXd reference = dense_bond_sum(model);
  const Eigen::MatrixXd difference = Eigen::MatrixXd(K) - Eigen::MatrixXd(reference);
  EXPECT_LE(difference.cwiseAbs().maxCoeff(), 1e-12 * Eigen::MatrixXd(reference).cwiseAbs().maxCoeff());
  EXPECT_LE((Eigen::MatrixXd(K) - Eigen::MatrixXd(K).transpose()).cwiseAbs().maxCoeff(), 1e-14 * Eigen::MatrixXd(K).cwiseAbs().maxCoeff());
}

TEST(DsmAssembly, ThreeDofMatrixIsTheTranslationalBlock) {
  const Model model = cubic_lattice(3, 2, 3, kRadius, 0.2, 0.0, 0.0, 8);
  const Eigen::MatrixXd K6 = Eigen::MatrixXd(assemble_bond_stiffness(model, 6));
  const Eigen::MatrixXd K3 = Eigen::MatrixXd(assemble_bond_stiffness(model, 3));
  const auto n = static_cast<Eigen::Index>(model.particles.size());
  for (Eigen::Index p = 0; p < n; ++p) {
    for (Eigen::Index q = 0; q < n; ++q) {
      EXPECT_LE((K3.block<3, 3>(3 * p, 3 * q) - K6.block<3, 3>(6 * p, 6 * q)).cwiseAbs().maxCoeff(),
                1e-9 * K6.cwiseAbs().maxCoeff());
    }
  }
}

TEST(DsmAssembly, SkewCouplingDiagonalsAreDroppedExactly) {
  // The translation-rotation blocks of a bond element are k [n]x: their diagonals are zero, held
  // by the probed element as round-off. Jittered lattice: no bond along an axis, so every other
  // entry of the element is nonzero.
  const Model model = cubic_lattice(2, 2, 2, kRadius, 0.2, 0.0, 0.0, 9);
  SparseMatrixRM K = assemble_bond_stiffness(model, 6);
  const Eigen::MatrixXd full = dense_bond_sum(model);
  const auto stored_before = K.nonZeros();
  DofConstraints none;
  none.fixed.assign(static_cast<std::size_t>(K.rows()), 0);
  none.value.assign(static_cast<std::size_t>(K.rows()), 0.0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(K.rows());
  apply_constraints(K, f, none);
  // 8 particles, 12 bonds: 8 diagonal and 24 off-diagonal 6x6 blocks of 36 entries, 6 of them zero.
  EXPECT_EQ(stored_before, 32 * 36);
  EXPECT_EQ(K.nonZeros(), 32 * 30);
  EXPECT_LE((Eigen::MatrixXd(K) - full).cwiseAbs().maxCoeff(), 1e-12 * full.cwiseAbs().maxCoeff());
}

/// A perfect lattice compressed between frictionless kinematic platens: every z-column of nz - 1
/// bonds in series carries the load, the lateral bonds stay unloaded, K = nx ny k_n / (nz - 1).
class DsmLattice : public ::testing::TestWithParam<std::tuple<int, SparseSolverKind>> {};

TEST_P(DsmLattice, ColumnsInSeriesStiffness) {
  const auto [dofs, solver] = GetParam();
  const int nx = 4, ny = 3, nz = 6;
  Model model = cubic_lattice(nx, ny, nz, kRadius, 0.0, 0.0, 0.0, 1);
  test::add_platen_materials(model);
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(1e-4));
  ASSERT_EQ(load.bottom.size(), static_cast<std::size_t>(nx * ny));
  ASSERT_EQ(load.top.size(), static_cast<std::size_t>(nx * ny));
  DsmOptions options;
  options.dofs = dofs;
  options.solver.kind = solver;
  options.solver.tolerance = 1e-10;
  const DsmResult r = solve_dsm_kinematic(model, load, options);
  const double k_n = model.bonds.stiffness[0].k_n;
  const double expected = nx * ny * k_n / (nz - 1);
  EXPECT_NEAR(r.stiffness, expected, 1e-8 * expected);
  EXPECT_NEAR(r.force_bottom, r.force_top, 1e-8 * r.force_top);  // equilibrium of the sample
  EXPECT_NEAR(r.youngs_modulus, r.stiffness * load.sample.length / load.sample.area, 1e-9 * r.youngs_modulus);
  // Uniform strain: a particle in layer k moves down by k / (nz - 1) of the platen displacement.
  for (std::size_t i = 0; i < model.particles.size(); ++i) {
    const double layer = static_cast<double>(static_cast<int>(i) % nz);
    EXPECT_NEAR(r.displacement[i].z, -load.displacement * layer / (nz - 1), 1e-7 * load.displacement);
    EXPECT_NEAR(r.displacement[i].x, 0.0, 1e-7 * load.displacement);
  }
}

INSTANTIATE_TEST_SUITE_P(DofsAndSolvers, DsmLattice,
                         ::testing::Combine(::testing::Values(6, 3),
                                            ::testing::Values(SparseSolverKind::cholmod, SparseSolverKind::amg_pcg)));

TEST(DsmKinematic, StiffnessScalesWithBondYoungsModulus) {
  Model soft = cubic_lattice(3, 3, 5, kRadius, 0.3, 0.0, 0.0, 4);
  test::add_platen_materials(soft);
  Model stiff = soft;
  for (auto& k : stiff.bonds.stiffness) {
    k.k_n *= 3.0;
    k.k_s *= 3.0;
    k.k_tor *= 3.0;
    k.k_ben *= 3.0;
  }
  const PlatenLoading load = test::layer_loading(soft, 5, 1e-4);
  EXPECT_NEAR(solve_dsm_kinematic(stiff, load).stiffness, 3.0 * solve_dsm_kinematic(soft, load).stiffness,
              1e-8 * solve_dsm_kinematic(stiff, load).stiffness);
}

TEST(DsmKinematic, DetachedParticlesAreHeldAndCounted) {
  Model model = cubic_lattice(3, 3, 4, kRadius, 0.0, 0.0, 0.0, 1);
  model.particles.add(999, {0.1, 0.1, 0.1}, kRadius, 7850.0);  // far away, unbonded
  model.finalize();
  test::add_platen_materials(model);
  const DsmResult r = solve_dsm_kinematic(model, test::layer_loading(model, 4, 1e-4));
  EXPECT_EQ(r.detached_particles, 1u);
  EXPECT_EQ(norm(r.displacement.back()), 0.0);
}

TEST(DsmKinematic, KeepsTheScenariosFixedDofs) {
  Model model = cubic_lattice(3, 3, 5, kRadius, 0.0, 0.0, 0.0, 1);
  test::add_platen_materials(model);
  const std::int32_t middle = (1 * 3 + 1) * 5 + 2;  // the centre particle of layer 2
  model.fix(middle, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0});  // held in all 6 DOFs: no rigid mode left
  const PlatenLoading load = test::layer_loading(model, 5, 1e-4);
  const DsmResult free = solve_dsm_kinematic(cubic_lattice(3, 3, 5, kRadius, 0.0, 0.0, 0.0, 1), load);
  const DsmResult held = solve_dsm_kinematic(model, load);
  EXPECT_EQ(norm(held.displacement[static_cast<std::size_t>(middle)]), 0.0);
  EXPECT_LT(free.displacement[static_cast<std::size_t>(middle)].z, -0.1 * load.displacement);
  EXPECT_GT(held.stiffness, free.stiffness);  // a support inside the column stiffens it
}

/// The linear DSM and the explicit DEM with the same constraints, on a jittered (disordered)
/// lattice: the DEM runs to Chen's rest criterion and must give the same stiffness and the same
/// displacement of every particle, up to the DEM's geometric nonlinearity (of the order of the strain).
TEST(DsmKinematic, MatchesQuasiStaticDemParticleByParticle) {
  const int nz = 6;
  Model model = cubic_lattice(4, 4, nz, kRadius, 0.2, 0.0, 0.0, 11);
  test::add_platen_materials(model);
  const double strain = 1e-5;
  const PlatenLoading load = test::layer_loading(model, nz, strain);
  const DsmResult dsm = solve_dsm_kinematic(model, load);
  KinematicCompressionSettings settings;
  settings.strain_rate = 100.0;
  const KinematicCompressionResult dem = run_kinematic_compression(model, load, settings);
  ASSERT_TRUE(dem.at_rest) << dem.steps << " steps, max speed " << dem.max_speed;
  EXPECT_NEAR(dem.stiffness, dsm.stiffness, 1e-3 * dsm.stiffness);
  const double field = max_relative_difference(model, load, dsm.displacement, dem.displacement);
  EXPECT_LT(field, 1e-4);  // measured 4e-6: the DEM's geometric nonlinearity at strain 1e-5
  RecordProperty("max_field_difference", std::to_string(field));
}

/// Hertz platens in series with the bond columns. Per column (nz - 1 bonds, k_col = k_n/(nz - 1))
/// with the force F shared by the nx ny columns: delta = F/(nx ny k_col) + 2 delta_H(F / (nx ny)),
/// delta_H(f) the Hertz overlap (3 f / (4 E* sqrt(R)))^(2/3) of one particle on a rigid-ish wall.
constexpr int kNx = 3, kNy = 3, kNz = 5;

/// The lattice of the Hertz-platen tests, with soft platen contacts so that the walls matter.
Model hertz_platen_lattice() {
  Model model = cubic_lattice(kNx, kNy, kNz, kRadius, 0.0, 0.0, 0.0, 1);
  test::add_platen_materials(model);
  model.contacts.materials[1].youngs_modulus = 2e8;
  return model;
}

/// The analytic columns-in-series system of hertz_platen_lattice (Hertz written out, not taken
/// from the contact law).
struct HertzColumns {
  explicit HertzColumns(const Model& model)
      : e_star(ContactTable(model.contacts)(0, 1).e_star), k_col(model.bonds.stiffness[0].k_n / (kNz - 1)) {}
  double e_star, k_col;
  double columns = kNx * kNy;
  /// Hertz overlap of one particle on the platen under force f.
  double overlap(double f) const { return std::pow(3.0 * f / (4.0 * e_star * std::sqrt(kRadius)), 2.0 / 3.0); }
  /// Platen force at travel w: bisection on w = F/(N k_col) + 2 delta_H(F/N).
  double platen_force(double w) const {
    double lo = 0.0, hi = columns * k_col * w;
    for (int it = 0; it < 200; ++it) {
      const double F = 0.5 * (lo + hi);
      (F / (columns * k_col) + 2.0 * overlap(F / columns) < w ? lo : hi) = F;
    }
    return 0.5 * (lo + hi);
  }
  /// The least-squares slope of F over [a, b] w, sampled densely as the DEM's force curve.
  double fitted_slope(double w, double a, double b) const {
    constexpr int kPoints = 2001;
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (int k = 0; k < kPoints; ++k) {
      const double x = (a + (b - a) * k / (kPoints - 1)) * w, y = platen_force(x);
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
    }
    return (kPoints * sxy - sx * sy) / (kPoints * sxx - sx * sx);
  }
  /// dF/dw at travel w: the columns in series with the two platens' tangents 3/2 f / delta.
  double tangent(double w) const {
    const double f = platen_force(w) / columns;
    const double contact = 1.5 * f / overlap(f);
    return columns / (1.0 / k_col + 2.0 / contact);
  }
};

TEST(DsmNonlinear, HertzPlatensInSeriesWithBondColumns) {
  const Model model = hertz_platen_lattice();
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(2e-4));
  DsmOptions options;
  options.nonlinear_tolerance = 1e-8;
  const DsmResult r = solve_dsm_nonlinear(model, load, options);
  const HertzColumns analytic(model);
  auto platen_force = [&](double w) { return analytic.platen_force(w); };
  const double w = load.displacement;
  // The DEM's fit over [0.2, 1] w; the three-point Gauss rule's error is ~1e-4 on Hertz curves.
  const double fitted = analytic.fitted_slope(w, 0.2, 1.0);
  EXPECT_NEAR(r.stiffness, fitted, 1e-3 * fitted);
  EXPECT_NEAR(r.secant_stiffness, platen_force(w) / w, 1e-5 * r.secant_stiffness);  // the path's end
  EXPECT_NEAR(r.force_bottom, r.force_top, 1e-5 * r.force_top);
  EXPECT_LT(r.stiffness, solve_dsm_kinematic(model, load).stiffness);
  EXPECT_GT(r.newton_iterations, 0);
}

/// The same system with the preconditioner forced to one AMG V-cycle (as above direct_limit): the
/// Krylov solver needs more iterations, the converged state is the same.
TEST(DsmNonlinear, AmgPreconditionerGivesTheSameHertzPlatenResult) {
  const Model model = hertz_platen_lattice();
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(2e-4));
  DsmOptions options;
  options.nonlinear_tolerance = 1e-8;
  const DsmResult direct = solve_dsm_nonlinear(model, load, options);
  options.solver.kind = SparseSolverKind::amg_pcg;
  const DsmResult amg = solve_dsm_nonlinear(model, load, options);
  EXPECT_NEAR(amg.stiffness, direct.stiffness, 1e-5 * direct.stiffness);
  EXPECT_NEAR(amg.secant_stiffness, direct.secant_stiffness, 1e-5 * direct.secant_stiffness);
  EXPECT_NEAR(amg.force_bottom, amg.force_top, 1e-5 * amg.force_top);
  EXPECT_GT(amg.newton_iterations, 0);
  RecordProperty("krylov_iterations_cholmod", std::to_string(direct.krylov_iterations));
  RecordProperty("krylov_iterations_amg", std::to_string(amg.krylov_iterations));
}


/// The linear DSM with its platen walls on the same system: Newton finds the platen contacts'
/// operating point in the middle of the fit window, and K is the tangent there.
class DsmWalls : public ::testing::TestWithParam<std::tuple<int, SparseSolverKind>> {};

TEST_P(DsmWalls, HertzPlatensTangentInTheMiddleOfTheFitWindow) {
  const auto [dofs, solver] = GetParam();
  const Model model = hertz_platen_lattice();
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(2e-4));
  DsmOptions options;
  options.dofs = dofs;
  options.solver.kind = solver;
  options.solver.tolerance = options.tangent_tolerance = 1e-10;
  options.operating_point_tolerance = 1e-8;
  const HertzColumns analytic(model);
  const double w = load.displacement, fitted = analytic.fitted_slope(w, 0.2, 1.0);
  double rule_error[2] = {0.0, 0.0};
  DsmResult r;
  for (const int points : {2, 8}) {
    // The tangents at the nodes of the fit window's rule (fit_window.hpp); two nodes are the
    // classical 0.6 -+ 0.4 / sqrt(5) of the window [0.2, 1].
    options.window_points = points;
    r = solve_dsm_linear(model, load, options);
    const WindowRule rule = tangent_rule(points, 0.2, 1.0);
    double expected = 0.0;
    for (std::size_t k = 0; k < rule.travel.size(); ++k) expected += rule.weight[k] * analytic.tangent(rule.travel[k] * w);
    const double upper = rule.travel.back() * w;
    EXPECT_NEAR(r.stiffness, expected, 1e-5 * r.stiffness) << points << " nodes";
    EXPECT_NEAR(r.force_top, analytic.platen_force(upper), 1e-5 * r.force_top);
    EXPECT_NEAR(r.force_bottom, r.force_top, 1e-5 * r.force_top);
    EXPECT_NEAR(r.secant_stiffness, r.force_top / upper, 1e-12 * r.secant_stiffness);
    EXPECT_GT(r.newton_iterations, 0);
    rule_error[points == 2 ? 0 : 1] = std::abs(r.stiffness / fitted - 1.0);
  }
  // What the DEM's least-squares fit of the force curve gives (the two-node rule's error: ~5e-4 on
  // Hertz, eight nodes' far less), not the tangent in the middle of the window (1 % more here) nor
  // the chord (1 % less).
  EXPECT_LT(rule_error[0], 1e-3);
  EXPECT_LT(rule_error[1], 0.1 * rule_error[0]);
  EXPECT_GT(std::abs(analytic.tangent(0.6 * w) / fitted - 1.0), 3e-3);
  // The walls' compliance: softer than the kinematic platens.
  EXPECT_LT(r.stiffness, 0.9 * solve_dsm_kinematic(model, load, options).stiffness);
  // Uniform strain in the columns between the overlaps: the field is the tangent line's at w.
  for (std::size_t i = 0; i < model.particles.size(); ++i) EXPECT_NEAR(r.displacement[i].x, 0.0, 1e-6 * load.displacement);
}

INSTANTIATE_TEST_SUITE_P(DofsAndSolvers, DsmWalls,
                         ::testing::Combine(::testing::Values(6, 3),
                                            ::testing::Values(SparseSolverKind::cholmod, SparseSolverKind::amg_pcg)));

/// Scales every bond's stiffness by 1e-4.
void soften_bonds(Model& model) {
  for (auto& k : model.bonds.stiffness) {
    k.k_n *= 1e-4;
    k.k_s *= 1e-4;
    k.k_tor *= 1e-4;
    k.k_ben *= 1e-4;
  }
}

/// Contacts superimposed on soft bonds (neighbours overlap by 0.002 R) with Hertz platens: each
/// column is links of a bond and a prestressed Hertz contact in parallel, in series with the two
/// platen contacts. At the operating point every link is compressed by e, f = k_b e +
/// F_H(delta_0 + e) - F_H(delta_0) per column, w = 2 delta_wall(f) + (nz - 1) e, and the tangent
/// is N / (2 / t_wall + (nz - 1) / (k_b + t_H(delta_0 + e))): the DSM must linearise the contacts
/// where they are pressed, not where they start.
TEST(DsmWalls, ContactsLinearisedAtTheirOperatingPoint) {
  Model model = hertz_platen_lattice();
  const double grown = 1.001 * kRadius;
  for (double& r : model.particles.radius) r = grown;
  model.contacts.particle_particle = true;
  soften_bonds(model);  // as soft as the contacts, so that both matter
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(2e-3));
  DsmOptions tight;
  tight.tangent_tolerance = 1e-8;
  tight.operating_point_tolerance = 1e-6;
  const DsmResult r = solve_dsm_linear(model, load, tight);
  const DsmResult by_default = solve_dsm_linear(model, load);

  const ContactTable table(model.contacts);
  const double e_wall = table(0, 1).e_star, e_pair = table(0, 0).e_star, r_pair = 0.5 * grown;
  const double k_b = model.bonds.stiffness[0].k_n, columns = kNx * kNy, delta0 = 2.0 * grown - 2.0 * kRadius;
  auto hertz = [](double e_star, double r_star, double d) { return 4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(d, 1.5); };
  auto bisect = [](auto&& g, double hi) {  // root of an increasing g on [0, hi]
    double lo = 0.0;
    for (int it = 0; it < 200; ++it) (g(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  };
  auto tangent_at = [&](double w, bool contacts_at_start) {
    auto link = [&](double f) {  // link compression e under column force f
      return bisect([&](double e) { return k_b * e + hertz(e_pair, r_pair, delta0 + e) - hertz(e_pair, r_pair, delta0) - f; }, w);
    };
    auto wall = [&](double f) { return std::pow(3.0 * f / (4.0 * e_wall * std::sqrt(grown)), 2.0 / 3.0); };
    const double f = bisect([&](double force) { return 2.0 * wall(force) + (kNz - 1) * link(force) - w; }, k_b * w);
    const double e = contacts_at_start ? 0.0 : link(f), t_wall = 1.5 * f / wall(f);
    const double t_link = k_b + 2.0 * e_pair * std::sqrt(r_pair * (delta0 + e));
    return columns / (2.0 / t_wall + (kNz - 1) / t_link);
  };
  // The tangents at the nodes of the fit window's rule (fit_window.hpp): this lattice has fewer
  // than 50 particles at each platen, so the default takes 24 nodes.
  const WindowRule rule = tangent_rule(24, 0.2, 1.0);
  auto averaged = [&](bool contacts_at_start) {
    double sum = 0.0;
    for (std::size_t k = 0; k < rule.travel.size(); ++k)
      sum += rule.weight[k] * tangent_at(rule.travel[k] * load.displacement, contacts_at_start);
    return sum;
  };
  const double expected = averaged(false);
  EXPECT_NEAR(r.stiffness, expected, 1e-5 * expected);
  EXPECT_NEAR(by_default.stiffness, expected, 1e-4 * expected);  // the default tolerances' cost
  // The contacts' tangent where they start would give a visibly softer sample here.
  const double at_start = averaged(true);
  EXPECT_GT(expected / at_start - 1.0, 1e-3);
  RecordProperty("stiffening_by_the_contacts_operating_point", std::to_string(expected / at_start - 1.0));
}

/// A column 30 particles tall with superimposed contacts (its jittered particles overlap some
/// neighbours and miss others by up to about a radius) at 1 % strain: the platen travel is 0.58 R,
/// the pairs' band (contact_listing_band) 0.5 R. The pairs in between never close, so K is the
/// one with every pair within the travel listed; the band is not a cut in the physics.
Model tall_jittered_column() {
  Model model = test::flat_ended_lattice(3, 3, 30, kRadius, 0.2, 7);
  model.contacts.particle_particle = true;
  soften_bonds(model);  // as soft as the contacts, so that both matter
  return model;
}

TEST(DsmWalls, ListsThePairsWithinTheirApproachNotTheWholeTravel) {
  const Model model = tall_jittered_column();
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(1e-2));
  const double travel_band = platen_listing_band(model, load);
  const DsmResult r = solve_dsm_linear(model, load);
  DsmOptions wide;
  wide.pair_band = travel_band;
  const DsmResult reference = solve_dsm_linear(model, load, wide);
  EXPECT_LT(r.pair_band, 0.9 * travel_band);
  EXPECT_LT(r.potential_contacts, reference.potential_contacts);  // pairs in between exist
  EXPECT_GT(r.max_pair_approach, 0.0);
  EXPECT_LT(r.max_pair_approach, 0.5 * (r.pair_band - 0.1 * kRadius));
  EXPECT_NEAR(r.stiffness, reference.stiffness, 1e-9 * reference.stiffness);
  RecordProperty("pairs_listed", std::to_string(r.potential_contacts) + " of " +
                                     std::to_string(reference.potential_contacts));
  RecordProperty("largest_approach_over_band", std::to_string(r.max_pair_approach / r.pair_band));
}

/// A band the pairs close by more than half of is widened to the platen travel.
TEST(DsmWalls, WidensThePairBandWhenTheListedPairsCloseByMuchOfIt) {
  const Model model = tall_jittered_column();
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(1e-2));
  DsmOptions narrow, wide;
  narrow.pair_band = 0.1 * kRadius + 1e-12;  // touching pairs only, no margin
  wide.pair_band = platen_listing_band(model, load);
  const DsmResult r = solve_dsm_linear(model, load, narrow);
  const DsmResult reference = solve_dsm_linear(model, load, wide);
  EXPECT_EQ(r.pair_band, wide.pair_band);
  EXPECT_EQ(r.potential_contacts, reference.potential_contacts);
  EXPECT_EQ(r.stiffness, reference.stiffness);
}

/// A sample that no platen can reach (its bonded cluster ends short of one platen: the top layer
/// is a loose particle that sets the sample's height) is refused with a message naming the cause.
TEST(DsmWalls, RefusesASampleOutOfReachOfAPlaten) {
  Model model = cubic_lattice(3, 3, 4, kRadius, 0.0, 0.0, 0.0, 1);
  model.particles.add(999, {2.0 * kRadius, 2.0 * kRadius, 20.0 * kRadius}, kRadius, 7850.0);  // unbonded, on top
  model.finalize();
  test::add_platen_materials(model);
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(1e-3));
  try {
    solve_dsm_linear(model, load);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("platen"), std::string::npos) << e.what();
  }
}

/// Contacts superimposed on the bonds of a column lattice whose particles overlap their
/// neighbours: each column is bonds and Hertz contacts in parallel, the contacts linearised at
/// their overlap, K = N (k_n + 2 E* sqrt(R* delta)) / (nz - 1) with the kinematic platens.
TEST(DsmKinematic, TouchingContactsAddTheirTangentStiffness) {
  const int nx = 3, ny = 3, nz = 5;
  Model model = cubic_lattice(nx, ny, nz, kRadius, 0.0, 0.0, 0.0, 1);
  test::add_platen_materials(model);
  const double grown = 1.001 * kRadius;  // overlap 0.002 R with each neighbour
  for (double& r : model.particles.radius) r = grown;
  model.contacts.particle_particle = true;
  const PlatenLoading load = test::layer_loading(model, nz, 1e-5);
  const DsmResult r = solve_dsm_kinematic(model, load);
  const double e_star = ContactTable(model.contacts)(0, 0).e_star;
  const double k_contact = 2.0 * e_star * std::sqrt(0.5 * grown * (2.0 * grown - 2.0 * kRadius));
  const double expected = nx * ny * (model.bonds.stiffness[0].k_n + k_contact) / (nz - 1);
  EXPECT_NEAR(r.stiffness, expected, 1e-6 * expected);
  // Replaced by the bonds: the same structure as without contacts.
  model.contacts.bonded = BondedContacts::replace;
  const double bonds_only = nx * ny * model.bonds.stiffness[0].k_n / (nz - 1);
  EXPECT_NEAR(solve_dsm_kinematic(model, load).stiffness, bonds_only, 1e-6 * bonds_only);
}

/// The body's E and nu (strain gauges on the middle third, compress/strain_gauge.hpp) of bond
/// columns between soft Hertz platens: the bonds' alone, N k_n L / A with L = 2R, and nu = 0, in
/// both DSMs, while K l / A also holds the platen contacts' compliance.
TEST(DsmBody, BondColumnsBetweenHertzPlatensGiveTheBondsModulus) {
  constexpr int nz = 10;
  Model model = cubic_lattice(kNx, kNy, nz, kRadius, 0.0, 0.0, 0.0, 1);
  test::add_platen_materials(model);
  model.contacts.materials[1].youngs_modulus = 2e8;
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(2e-4));
  const double expected = kNx * kNy * model.bonds.stiffness[0].k_n * 2.0 * kRadius / load.sample.area;
  DsmOptions options;
  options.nonlinear_tolerance = 1e-8;
  options.operating_point_tolerance = 1e-8;
  for (const DsmResult& r : {solve_dsm_linear(model, load, options), solve_dsm_nonlinear(model, load, options)}) {
    ASSERT_TRUE(r.body.valid);
    EXPECT_EQ(r.gauge_particles, static_cast<std::size_t>(kNx * kNy * 4));  // the layers at z = 6R ... 12R of 0 ... 18R
    EXPECT_NEAR(r.body.youngs_modulus / expected, 1.0, 1e-6);
    EXPECT_NEAR(r.body.poissons_ratio, 0.0, 1e-9);
    EXPECT_LT(r.youngs_modulus, 0.9 * r.body.youngs_modulus);  // the platens' Hertz contacts
  }
}

}  // namespace
}  // namespace bpm
