// solve_spd (src/dsm/sparse_solver.*): CHOLMOD and hypre AMG-PCG on the stiffness of a bonded cubic
// lattice clamped at the bottom and loaded at the top, against each other and against Eigen's LDLT;
// SpdPreconditioner (CHOLMOD's factor or one AMG V-cycle) on the same systems.
#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/dem_helpers.hpp"
#include "solvers/sparse_solver.hpp"
#include "statics/static_assembly.hpp"
#include "statics/static_solver.hpp"

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
  const Eigen::SparseMatrix<double> K_full =
      Eigen::SparseMatrix<double>(assemble_stiffness(model, 6, {}));
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

/// Shared by several tests; solve_spd lends its K to hypre and restores it.
Problem& lattice10() {
  static Problem p = lattice_problem(10, 6, true);
  return p;
}

/// K's arrays, entry by entry (solve_spd must hand K back as it got it).
bool same_arrays(const SparseMatrixRM& a, const SparseMatrixRM& b) {
  return a.rows() == b.rows() && a.nonZeros() == b.nonZeros() &&
         std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.rows() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr()) &&
         std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr());
}

TEST(SparseSolverTest, CholmodMatchesEigenLdltOnASmallLattice) {
  Problem p = lattice_problem(4, 6, true);
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
  Problem& p = lattice10();
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
  Problem& p = lattice10();
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
  Problem& p = lattice10();
  Eigen::VectorXd u;
  solve_spd(p.K, p.f, u, with(SparseSolverKind::cholmod));
  const SparseSolveReport r = solve_spd(p.K, p.f, u, with(SparseSolverKind::amg_pcg, 1e-8));
  EXPECT_LE(r.iterations, 1);  // hypre's PCG checks after its first step
}

TEST(SparseSolverTest, TranslationOnlySystemWithBlockSize3) {
  Problem p = lattice_problem(10, 3, true);
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
  Problem p = lattice_problem(5, 6, false);  // nothing held: six rigid-body modes
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
  Problem p = lattice_problem_xyz(1, 1, 400, 6, true);
  Eigen::VectorXd u;
  const SparseSolveReport r = solve_spd(p.K, p.f, u, with(SparseSolverKind::cholmod));
  // Round-off bounds the residual by ~eps ||K|| ||u|| / ||f||, large here: the tip sways far.
  EXPECT_LT(r.relative_residual, 1e-6);
  EXPECT_GT(u[p.top_x.front()], 0.0);
}

TEST(SparseSolverTest, AmgThatMissesTheToleranceIsAnInputError) {
  Problem& p = lattice10();
  const SparseMatrixRM before = p.K;
  SparseSolverOptions o = with(SparseSolverKind::amg_pcg, 1e-12);
  o.max_iterations = 3;
  Eigen::VectorXd u;
  try {
    solve_spd(p.K, p.f, u, o);
    ADD_FAILURE() << "3 iterations reached 1e-12";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--solver cholmod"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(same_arrays(p.K, before));  // restored on the way out, too
}

TEST(SparseSolverTest, AmgReadsKInPlaceAndHandsItBackUnchanged) {
  // hypre wants each row's diagonal entry first: K's rows are reordered while it is lent.
  Problem p = lattice_problem(6, 6, true);
  const SparseMatrixRM before = p.K;
  Eigen::VectorXd u_amg, u_copy;
  solve_spd(p.K, p.f, u_amg, with(SparseSolverKind::amg_pcg, 1e-10));
  EXPECT_TRUE(same_arrays(p.K, before));
  SparseMatrixRM copy = before;
  solve_spd(copy, p.f, u_copy, with(SparseSolverKind::amg_pcg, 1e-10));
  EXPECT_EQ(u_amg, u_copy);  // the same arrays give the same iterates, bit for bit
  EXPECT_LE(residual(p, u_amg), 1e-10);
}

TEST(SparseSolverTest, AmgGivesTheSameSolutionForAnyThreadCount) {
  // The V-cycle's Chebyshev smoother needs only products, and CG's dot products sum fixed blocks
  // in a fixed order: no rounding depends on the thread count.
  Problem p = lattice_problem(12, 6, true);
  const int threads = omp_get_max_threads();
  Eigen::VectorXd one, two;
  omp_set_num_threads(1);
  const SparseSolveReport r1 = solve_spd(p.K, p.f, one, with(SparseSolverKind::amg_pcg, 1e-8));
  omp_set_num_threads(2);
  const SparseSolveReport r2 = solve_spd(p.K, p.f, two, with(SparseSolverKind::amg_pcg, 1e-8));
  omp_set_num_threads(threads);
  EXPECT_EQ(r1.iterations, r2.iterations);
  EXPECT_EQ(one, two);
  EXPECT_GT(r1.levels, 1);
  EXPECT_LE(residual(p, one), 1e-8);
}

TEST(SparseSolverTest, AutomaticPicksBySize) {
  Problem p = lattice_problem(4, 6, true);
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
  Problem p = lattice_problem(3, 6, true);
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

// SpdPreconditioner: CHOLMOD's factor or one BoomerAMG V-cycle, applied many times (the nonlinear
// DSM's Krylov preconditioner).

/// Deterministic random vector, entries uniform in [-1, 1].
Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = uniform(generator);
  return v;
}

/// Preconditioned conjugate gradients from u = 0 with the preconditioner's apply; returns the
/// iterations to ||f - K u|| <= tolerance ||f|| (max_iterations + 1 if not reached).
int preconditioned_cg(const SparseMatrixRM& K, const SpdPreconditioner& M, const Eigen::VectorXd& f,
                      Eigen::VectorXd& u, double tolerance, int max_iterations) {
  u = Eigen::VectorXd::Zero(f.size());
  Eigen::VectorXd r = f, z, p, q;
  M.apply(r, z);
  p = z;
  double rz = r.dot(z);
  for (int it = 1; it <= max_iterations; ++it) {
    q = K * p;
    const double alpha = rz / p.dot(q);
    u += alpha * p;
    r -= alpha * q;
    if (r.norm() <= tolerance * f.norm()) return it;
    M.apply(r, z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return max_iterations + 1;
}

TEST(SpdPreconditionerTest, CholmodAppliesTheExactInverseToAResidual) {
  Problem& p = lattice10();
  const SpdPreconditioner M(SparseMatrixRM(p.K), with(SparseSolverKind::cholmod));
  EXPECT_EQ(M.kind(), SparseSolverKind::cholmod);
  // The residual of a rough guess, as in a Newton step.
  const Eigen::VectorXd guess = 1e-6 * random_vector(p.K.rows(), 1);
  const Eigen::VectorXd r = p.f - p.K * guess;
  Eigen::VectorXd z;
  M.apply(r, z);
  ASSERT_EQ(z.size(), r.size());
  EXPECT_LT((r - p.K * z).norm() / r.norm(), 1e-12);
  // Again, with another vector: the factor is reused.
  const Eigen::VectorXd b = random_vector(p.K.rows(), 2);
  M.apply(b, z);
  EXPECT_LT((b - p.K * z).norm() / b.norm(), 1e-12);
}

/// One V-cycle from zero on a random right-hand side b, measured on the 10 x 10 x 10 lattice
/// (seeds 3-5). With forces ~1 N and moments ~R x 1 N (physical units, as the nonlinear DSM scales
/// its residual) ||b - K z|| falls 4.3-4.6x (4x4x4 to 14x14x14 lattices: 3.7-4.6x). In the norm of
/// the diagonally scaled system, ||D^-1/2 (b - K z)|| with D = diag(K), independent of units, a
/// unit random b falls 12-13x. (The plain 2-norm of such a unit b is meaningless: a moment of 1 N m
/// on a rotation row, ~R^2 softer than a translation row, drives rotations whose translational
/// forces raise ||b - K z|| 60x.)
TEST(SpdPreconditionerTest, OneAmgVCycleReducesTheResidualOfARandomRightHandSide) {
  Problem& p = lattice10();
  const SpdPreconditioner M(SparseMatrixRM(p.K), with(SparseSolverKind::amg_pcg));
  EXPECT_EQ(M.kind(), SparseSolverKind::amg_pcg);
  const Eigen::VectorXd d = p.K.diagonal().cwiseSqrt().cwiseInverse();
  for (const unsigned seed : {3u, 4u, 5u}) {
    Eigen::VectorXd b = random_vector(p.K.rows(), seed);
    Eigen::VectorXd z;
    M.apply(b, z);
    ASSERT_EQ(z.size(), b.size());
    const double scaled = d.cwiseProduct(b).norm() / d.cwiseProduct(b - p.K * z).norm();
    EXPECT_GT(scaled, 5.0) << "seed " << seed;
    for (Eigen::Index i = 3; i < b.size(); i += 6) b.segment<3>(i) *= 1e-3;  // moments ~R x 1 N
    M.apply(b, z);
    const double plain = b.norm() / (b - p.K * z).norm();
    EXPECT_GT(plain, 3.0) << "seed " << seed;
    RecordProperty("reduction_seed_" + std::to_string(seed),
                   std::to_string(plain) + " (scaled " + std::to_string(scaled) + ")");
  }
}

TEST(SpdPreconditionerTest, AmgVCycleIsAFixedLinearMap) {
  Problem& p = lattice10();
  const SpdPreconditioner M(SparseMatrixRM(p.K), with(SparseSolverKind::amg_pcg));
  const Eigen::VectorXd a = random_vector(p.K.rows(), 6), b = random_vector(p.K.rows(), 7);
  Eigen::VectorXd za, zb, zab, za_again;
  M.apply(a, za);
  M.apply(b, zb);
  M.apply(2.0 * a - b, zab);
  M.apply(a, za_again);
  EXPECT_EQ(za, za_again);  // no state carried from one apply to the next: deterministic
  EXPECT_LT((zab - (2.0 * za - zb)).norm(), 1e-12 * zab.norm());
  // Symmetric, as CG needs: the same smoother before and after the coarse correction.
  EXPECT_NEAR(b.dot(za), a.dot(zb), 1e-10 * std::abs(a.dot(zb)));
}

TEST(SpdPreconditionerTest, RepeatedAmgApplicationInCgConvergesToTheDirectSolution) {
  Problem& p = lattice10();
  const SpdPreconditioner amg(SparseMatrixRM(p.K), with(SparseSolverKind::amg_pcg));
  const SpdPreconditioner direct(SparseMatrixRM(p.K), with(SparseSolverKind::cholmod));
  Eigen::VectorXd u_amg, u_direct;
  const int iterations = preconditioned_cg(p.K, amg, p.f, u_amg, 1e-8, 200);
  EXPECT_LT(iterations, 60);  // multigrid: solve_spd's AMG-PCG takes about as many
  RecordProperty("amg_cg_iterations", std::to_string(iterations));
  EXPECT_EQ(preconditioned_cg(p.K, direct, p.f, u_direct, 1e-8, 200), 1);  // the exact inverse
  EXPECT_LT((u_amg - u_direct).norm(), 1e-5 * u_direct.norm());
}

TEST(SpdPreconditionerTest, TranslationOnlyAmgWithBlockSize3Converges) {
  const Problem p = lattice_problem(8, 3, true);
  const SpdPreconditioner M(SparseMatrixRM(p.K), with(SparseSolverKind::amg_pcg, 1e-8, 3));
  Eigen::VectorXd u;
  EXPECT_LT(preconditioned_cg(p.K, M, p.f, u, 1e-8, 200), 60);
  EXPECT_LE(residual(p, u), 1e-8);
}

TEST(SpdPreconditionerTest, AutomaticPicksBySizeAndUncompressedMatrixIsAccepted) {
  const Problem p = lattice_problem(4, 6, true);
  SparseMatrixRM K = p.K;
  K.uncompress();
  ASSERT_FALSE(K.isCompressed());
  const auto n = static_cast<std::size_t>(p.K.rows());
  SparseSolverOptions o = with(SparseSolverKind::automatic);
  o.direct_limit = n;
  const SpdPreconditioner direct(SparseMatrixRM(K), o);
  EXPECT_EQ(direct.kind(), SparseSolverKind::cholmod);
  o.direct_limit = n - 1;
  const SpdPreconditioner amg(SparseMatrixRM(K), o);
  EXPECT_EQ(amg.kind(), SparseSolverKind::amg_pcg);
  Eigen::VectorXd z;
  direct.apply(p.f, z);
  EXPECT_LT(residual(p, z), 1e-12);
  amg.apply(p.f, z);
  EXPECT_LT(residual(p, z), 1.0);  // one V-cycle: an approximation
  EXPECT_THROW(amg.apply(Eigen::VectorXd::Zero(3), z), std::invalid_argument);
}

// ShiftedSpdSolver's coarse space (the DSM with walls' rigid-body modes, deflated in CG).

/// The free 8 x 8 x 8 lattice (nothing held) on soft springs: 1e-4 of K's mean diagonal on the
/// translations of the bottom and top layers, as the platen springs hold the DSM's sample. Z: its
/// six rigid-body modes, unit columns.
struct SoftlyHeld {
  Problem p;
  Eigen::VectorXd springs;
  Eigen::MatrixXd Z;
};

SoftlyHeld softly_held_lattice() {
  constexpr int n = 8;
  const Model model = test::cubic_lattice(n, n, n, 1e-3, 0.1, 0.0, 0.0, 7);
  SoftlyHeld s;
  s.p = lattice_problem(n, 6, false);
  const Eigen::Index rows = s.p.K.rows();
  const double spring = 1e-4 * s.p.K.diagonal().mean();
  s.springs = Eigen::VectorXd::Zero(rows);
  s.Z = Eigen::MatrixXd::Zero(rows, 6);
  for (std::size_t q = 0; q < model.particles.size(); ++q) {
    const int layer = static_cast<int>(q % n);
    const auto at = static_cast<Eigen::Index>(6 * q);
    if (layer == 0 || layer == n - 1) s.springs.segment(at, 3).setConstant(spring);
    const Vec3 X = model.particles.position[q];
    for (int k = 0; k < 3; ++k) {
      s.Z(at + k, k) = 1.0;
      Vec3 a{};
      a[k] = 1.0;
      const Vec3 u = cross(a, X);
      for (int c = 0; c < 3; ++c) s.Z(at + c, 3 + k) = u[c];
      s.Z(at + 3 + k, 3 + k) = 1.0;
    }
  }
  s.Z.colwise().normalize();
  return s;
}

TEST(ShiftedSpdSolverTest, RigidBodyCoarseSpaceGivesTheSameSolutionInFewerIterations) {
  const SoftlyHeld s = softly_held_lattice();
  const Eigen::Index rows = s.p.K.rows();
  const SparseMatrixRM& K = s.p.K;
  int iterations[2] = {};
  for (const bool deflated : {false, true}) {
    SparseSolverOptions o = with(SparseSolverKind::amg_pcg);
    o.nodal_coarsening = deflated;
    ShiftedSpdSolver amg(SparseMatrixRM(K), o);
    if (deflated) amg.set_coarse_space(s.Z);
    for (const double scale : {1.0, 2.0}) {  // the second solve: another shift, K Z reused
      Eigen::VectorXd u = Eigen::VectorXd::Zero(rows), reference;
      const Eigen::VectorXd shift = scale * s.springs;
      ShiftedSpdSolver check(SparseMatrixRM(K), with(SparseSolverKind::cholmod));
      check.solve(shift, s.p.f, reference, 1e-10);
      const SparseSolveReport report = amg.solve(shift, s.p.f, u, 1e-8);
      EXPECT_LE(report.relative_residual, 1e-8);
      EXPECT_LT((u - reference).norm(), 1e-5 * reference.norm()) << "deflated " << deflated;
      iterations[deflated] += report.iterations;
    }
  }
  EXPECT_LT(iterations[1], iterations[0]);
}

}  // namespace
}  // namespace bpm
