// solve_spd (src/dsm/sparse_solver.*): CHOLMOD and hypre AMG-PCG on the stiffness of a bonded cubic
// lattice clamped at the bottom and loaded at the top, against each other and against Eigen's LDLT.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/dem_helpers.hpp"
#include "dsm/sparse_solver.hpp"
#include "linear/static_solver.hpp"

namespace bpm {
namespace {

struct Problem {
  SparseMatrixRM K;
  Eigen::VectorXd f;
  std::vector<Eigen::Index> top_x;  ///< reduced index of the x translation of each top particle
};

/// nx x ny x nz lattice (R = 1 mm, TBBM steel bonds, 10 % jitter). `dofs` = 6 keeps translations
/// and rotations, 3 only translations (rotations held: a principal submatrix, still SPD). With
/// `clamp_bottom` the bottom layer's DOFs are removed; the top layer carries 1 N along x and -2 N
/// along z per particle, plus 1e-3 N m about y with 6 DOFs.
Problem lattice_problem_xyz(int nx, int ny, int nz, int dofs, bool clamp_bottom) {
  const Model model = test::cubic_lattice(nx, ny, nz, 1e-3, 0.1, 0.0, 0.0, 7);
  const Eigen::SparseMatrix<double> K_full = assemble_stiffness(model);
  // cubic_lattice numbers particles (i * ny + j) * nz + k with k along z.
  auto layer = [nz](std::size_t p) { return static_cast<int>(p % static_cast<std::size_t>(nz)); };
  std::vector<Eigen::Index> reduced(static_cast<std::size_t>(K_full.rows()), -1);
  Eigen::Index n_free = 0;
  Problem problem;
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    if (clamp_bottom && layer(p) == 0) continue;
    for (int k = 0; k < dofs; ++k) reduced[6 * p + k] = n_free++;
  }
  problem.f = Eigen::VectorXd::Zero(n_free);
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    if (layer(p) != nz - 1) continue;
    problem.top_x.push_back(reduced[6 * p]);
    problem.f[reduced[6 * p]] = 1.0;
    problem.f[reduced[6 * p + 2]] = -2.0;
    if (dofs == 6) problem.f[reduced[6 * p + 4]] = 1e-3;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (Eigen::Index col = 0; col < K_full.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(K_full, col); it; ++it) {
      const Eigen::Index r = reduced[it.row()], c = reduced[it.col()];
      if (r >= 0 && c >= 0) triplets.emplace_back(r, c, it.value());
    }
  }
  problem.K.resize(n_free, n_free);
  problem.K.setFromTriplets(triplets.begin(), triplets.end());
  return problem;
}

Problem lattice_problem(int n, int dofs, bool clamp_bottom) {
  return lattice_problem_xyz(n, n, n, dofs, clamp_bottom);
}

double residual(const Problem& p, const Eigen::VectorXd& u) {
  return (p.f - p.K * u).norm() / p.f.norm();
}

SparseSolverOptions with(SparseSolverKind kind, double tolerance = 1e-8, int block_size = 6) {
  SparseSolverOptions o;
  o.kind = kind;
  o.tolerance = tolerance;
  o.block_size = block_size;
  return o;
}

const Problem& lattice10() {
  static const Problem p = lattice_problem(10, 6, true);
  return p;
}

TEST(SparseSolverTest, CholmodMatchesEigenLdltOnASmallLattice) {
  const Problem p = lattice_problem(4, 6, true);
  Eigen::VectorXd u;
  const SparseSolveReport r = solve_spd(p.K, p.f, u, with(SparseSolverKind::cholmod));
  EXPECT_EQ(r.used, SparseSolverKind::cholmod);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_GT(r.peak_bytes, 0u);
  const Eigen::SparseMatrix<double> K = p.K;
  const Eigen::VectorXd reference =
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(K).solve(p.f);
  EXPECT_LT((u - reference).norm(), 1e-9 * reference.norm());
  EXPECT_LT(residual(p, u), 1e-12);
  EXPECT_NEAR(r.relative_residual, residual(p, u), 1e-15);
}

TEST(SparseSolverTest, CholmodAndAmgAgreeOnA10x10x10Lattice) {
  const Problem& p = lattice10();
  Eigen::VectorXd u_direct, u_amg;
  const SparseSolveReport direct = solve_spd(p.K, p.f, u_direct, with(SparseSolverKind::cholmod));
  const SparseSolveReport amg = solve_spd(p.K, p.f, u_amg, with(SparseSolverKind::amg_pcg, 1e-8));
  EXPECT_EQ(direct.used, SparseSolverKind::cholmod);
  EXPECT_EQ(amg.used, SparseSolverKind::amg_pcg);
  EXPECT_LT(residual(p, u_direct), 1e-10);
  EXPECT_LE(residual(p, u_amg), 1e-8);
  EXPECT_NEAR(amg.relative_residual, residual(p, u_amg), 1e-12);
  EXPECT_GT(amg.iterations, 0);
  EXPECT_LT(amg.iterations, 200);  // multigrid: far fewer than the 5400 unknowns
  EXPECT_LT((u_amg - u_direct).norm(), 1e-5 * u_direct.norm());
  // The top layer moves with the load, along +x.
  for (const Eigen::Index i : p.top_x) EXPECT_GT(u_direct[i], 0.0);
}

TEST(SparseSolverTest, AmgReportsTrueResidualAtTheRequestedTolerance) {
  const Problem& p = lattice10();
  Eigen::VectorXd loose, tight;
  const SparseSolveReport r_loose =
      solve_spd(p.K, p.f, loose, with(SparseSolverKind::amg_pcg, 1e-4));
  const SparseSolveReport r_tight =
      solve_spd(p.K, p.f, tight, with(SparseSolverKind::amg_pcg, 1e-10));
  EXPECT_LE(residual(p, loose), 1e-4);
  EXPECT_LE(residual(p, tight), 1e-10);
  EXPECT_LT(r_loose.iterations, r_tight.iterations);
}

TEST(SparseSolverTest, AmgStartsFromTheGivenSolution) {
  const Problem& p = lattice10();
  Eigen::VectorXd u;
  solve_spd(p.K, p.f, u, with(SparseSolverKind::cholmod));
  const SparseSolveReport r = solve_spd(p.K, p.f, u, with(SparseSolverKind::amg_pcg, 1e-8));
  EXPECT_LE(r.iterations, 1);  // hypre's PCG checks after its first step
}

TEST(SparseSolverTest, TranslationOnlySystemWithBlockSize3) {
  const Problem p = lattice_problem(10, 3, true);
  Eigen::VectorXd u_direct, u_amg;
  solve_spd(p.K, p.f, u_direct, with(SparseSolverKind::cholmod));
  const SparseSolveReport amg =
      solve_spd(p.K, p.f, u_amg, with(SparseSolverKind::amg_pcg, 1e-8, 3));
  EXPECT_LT(residual(p, u_direct), 1e-10);
  EXPECT_LE(residual(p, u_amg), 1e-8);
  EXPECT_LT(amg.iterations, 200);
  EXPECT_LT((u_amg - u_direct).norm(), 1e-5 * u_direct.norm());
}

TEST(SparseSolverTest, SingularSystemIsAnInputErrorForBothSolvers) {
  const Problem p = lattice_problem(5, 6, false);  // nothing held: six rigid-body modes
  Eigen::VectorXd u;
  try {
    solve_spd(p.K, p.f, u, with(SparseSolverKind::cholmod));
    ADD_FAILURE() << "CHOLMOD accepted a singular K";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rigid-body mode"), std::string::npos) << e.what();
  }
  SparseSolverOptions o = with(SparseSolverKind::amg_pcg);
  o.max_iterations = 200;
  EXPECT_THROW(solve_spd(p.K, p.f, u, o), InputError);
}

TEST(SparseSolverTest, SlenderColumnIsNotMistakenForAMechanism) {
  // A column of 400 particles clamped at the base, pushed sideways at the top: cond(K) grows as
  // n^4 in bending, yet no pivot comes near the round-off of a free rigid-body mode.
  const Problem p = lattice_problem_xyz(1, 1, 400, 6, true);
  Eigen::VectorXd u;
  const SparseSolveReport r = solve_spd(p.K, p.f, u, with(SparseSolverKind::cholmod));
  // Round-off bounds the residual by ~eps ||K|| ||u|| / ||f||, large here: the tip sways far.
  EXPECT_LT(r.relative_residual, 1e-6);
  EXPECT_GT(u[p.top_x.front()], 0.0);
}

TEST(SparseSolverTest, AmgThatMissesTheToleranceIsAnInputError) {
  const Problem& p = lattice10();
  SparseSolverOptions o = with(SparseSolverKind::amg_pcg, 1e-12);
  o.max_iterations = 3;
  Eigen::VectorXd u;
  try {
    solve_spd(p.K, p.f, u, o);
    ADD_FAILURE() << "3 iterations reached 1e-12";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--solver cholmod"), std::string::npos) << e.what();
  }
}

TEST(SparseSolverTest, AutomaticPicksBySize) {
  const Problem p = lattice_problem(4, 6, true);
  const auto n = static_cast<std::size_t>(p.K.rows());
  SparseSolverOptions o = with(SparseSolverKind::automatic);
  Eigen::VectorXd u;
  o.direct_limit = n;
  EXPECT_EQ(solve_spd(p.K, p.f, u, o).used, SparseSolverKind::cholmod);
  o.direct_limit = n - 1;
  u.resize(0);
  EXPECT_EQ(solve_spd(p.K, p.f, u, o).used, SparseSolverKind::amg_pcg);
  EXPECT_LE(residual(p, u), 1e-8);
}

TEST(SparseSolverTest, UncompressedMatrixIsAccepted) {
  const Problem p = lattice_problem(3, 6, true);
  SparseMatrixRM K = p.K;
  K.uncompress();
  ASSERT_FALSE(K.isCompressed());
  Eigen::VectorXd u_direct, u_amg;
  solve_spd(K, p.f, u_direct, with(SparseSolverKind::cholmod));
  solve_spd(K, p.f, u_amg, with(SparseSolverKind::amg_pcg));
  EXPECT_LT(residual(p, u_direct), 1e-12);
  EXPECT_LE(residual(p, u_amg), 1e-8);
}

TEST(SparseSolverTest, NamesRoundTripAndUnknownNameIsAnInputError) {
  for (const auto kind :
       {SparseSolverKind::automatic, SparseSolverKind::cholmod, SparseSolverKind::amg_pcg}) {
    EXPECT_EQ(parse_sparse_solver(to_string(kind), "--solver"), kind);
  }
  EXPECT_EQ(to_string(SparseSolverKind::amg_pcg), "amg");
  try {
    parse_sparse_solver("mumps", "--solver");
    ADD_FAILURE() << "'mumps' was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--solver"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown solver 'mumps'"), std::string::npos) << what;
    EXPECT_NE(what.find("auto, cholmod, amg"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace bpm
