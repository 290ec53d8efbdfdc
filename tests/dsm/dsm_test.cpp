// The direct stiffness method: assembly from the bond element, kinematic platens against the
// analytic columns-in-series stiffness and against the explicit DEM with the same constraints
// (particle by particle), the nonlinear variant with Hertz wall springs against its analytic
// series solution.
#include <gtest/gtest.h>

#include <cmath>

#include "compress/kinematic_compression.hpp"
#include "dsm/dsm_assembly.hpp"
#include "dsm/dsm_constraints.hpp"
#include "dsm/dsm_helpers.hpp"
#include "dsm/dsm_linear.hpp"
#include "dsm/dsm_nonlinear.hpp"
#include "linear/static_solver.hpp"

namespace bpm {
namespace {

using test::cubic_lattice;

constexpr double kRadius = 1e-3;

TEST(DsmAssembly, SixDofMatrixEqualsTheStaticSolversAssembly) {
  const Model model = cubic_lattice(3, 3, 4, kRadius, 0.2, 0.0, 0.0, 7);
  const SparseMatrixRM K = assemble_bond_stiffness(model, 6);
  const Eigen::SparseMatrix<double> reference = assemble_stiffness(model);
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
  const Eigen::MatrixXd full = Eigen::MatrixXd(assemble_stiffness(model));
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
  const DsmResult r = solve_dsm_linear(model, load, options);
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

TEST(DsmLinear, StiffnessScalesWithBondYoungsModulus) {
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
  EXPECT_NEAR(solve_dsm_linear(stiff, load).stiffness, 3.0 * solve_dsm_linear(soft, load).stiffness,
              1e-8 * solve_dsm_linear(stiff, load).stiffness);
}

TEST(DsmLinear, DetachedParticlesAreHeldAndCounted) {
  Model model = cubic_lattice(3, 3, 4, kRadius, 0.0, 0.0, 0.0, 1);
  model.particles.add(999, {0.1, 0.1, 0.1}, kRadius, 7850.0);  // far away, unbonded
  model.finalize();
  test::add_platen_materials(model);
  const DsmResult r = solve_dsm_linear(model, test::layer_loading(model, 4, 1e-4));
  EXPECT_EQ(r.detached_particles, 1u);
  EXPECT_EQ(norm(r.displacement.back()), 0.0);
}

TEST(DsmLinear, KeepsTheScenariosFixedDofs) {
  Model model = cubic_lattice(3, 3, 5, kRadius, 0.0, 0.0, 0.0, 1);
  test::add_platen_materials(model);
  const std::int32_t middle = (1 * 3 + 1) * 5 + 2;  // the centre particle of layer 2
  model.fix(middle, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0});  // held in all 6 DOFs: no rigid mode left
  const PlatenLoading load = test::layer_loading(model, 5, 1e-4);
  const DsmResult free = solve_dsm_linear(cubic_lattice(3, 3, 5, kRadius, 0.0, 0.0, 0.0, 1), load);
  const DsmResult held = solve_dsm_linear(model, load);
  EXPECT_EQ(norm(held.displacement[static_cast<std::size_t>(middle)]), 0.0);
  EXPECT_LT(free.displacement[static_cast<std::size_t>(middle)].z, -0.1 * load.displacement);
  EXPECT_GT(held.stiffness, free.stiffness);  // a support inside the column stiffens it
}

/// The linear DSM and the explicit DEM with the same constraints, on a jittered (disordered)
/// lattice: the DEM runs to Chen's rest criterion and must give the same stiffness and the same
/// displacement of every particle, up to the DEM's geometric nonlinearity (of the order of the strain).
TEST(DsmLinear, MatchesQuasiStaticDemParticleByParticle) {
  const int nz = 6;
  Model model = cubic_lattice(4, 4, nz, kRadius, 0.2, 0.0, 0.0, 11);
  test::add_platen_materials(model);
  const double strain = 1e-5;
  const PlatenLoading load = test::layer_loading(model, nz, strain);
  const DsmResult dsm = solve_dsm_linear(model, load);
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

TEST(DsmNonlinear, HertzPlatensInSeriesWithBondColumns) {
  const int nx = kNx, ny = kNy, nz = kNz;
  const Model model = hertz_platen_lattice();
  const PlatenLoading load = make_platen_loading(model, test::compression_along_z(2e-4));
  DsmOptions options;
  options.nonlinear_tolerance = 1e-8;
  const DsmResult r = solve_dsm_nonlinear(model, load, options);
  const ContactTable table(model.contacts);
  const double e_star = table(0, 1).e_star;
  const double columns = nx * ny, k_col = model.bonds.stiffness[0].k_n / (nz - 1);
  auto overlap = [&](double f) { return std::pow(3.0 * f / (4.0 * e_star * std::sqrt(kRadius)), 2.0 / 3.0); };
  auto platen_force = [&](double w) {  // bisection on w = F/(N k_col) + 2 delta_H(F/N)
    double lo = 0.0, hi = columns * k_col * w;
    for (int it = 0; it < 200; ++it) {
      const double F = 0.5 * (lo + hi);
      (F / (columns * k_col) + 2.0 * overlap(F / columns) < w ? lo : hi) = F;
    }
    return 0.5 * (lo + hi);
  };
  const double w = load.displacement;
  const double chord = (platen_force(w) - platen_force(0.2 * w)) / (0.8 * w);  // the DEM's fit window
  EXPECT_NEAR(r.stiffness, chord, 1e-5 * chord);
  EXPECT_NEAR(r.secant_stiffness, platen_force(w) / w, 1e-5 * r.secant_stiffness);
  EXPECT_NEAR(r.force_bottom, r.force_top, 1e-5 * r.force_top);
  EXPECT_LT(r.stiffness, solve_dsm_linear(model, load).stiffness);
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

}  // namespace
}  // namespace bpm
