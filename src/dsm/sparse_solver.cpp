#include "dsm/sparse_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dsm/cholmod_factor.hpp"
#include "dsm/hypre_support.hpp"

namespace bpm {

std::string_view to_string(SparseSolverKind kind) {
  switch (kind) {
    case SparseSolverKind::automatic:
      return "auto";
    case SparseSolverKind::cholmod:
      return "cholmod";
    case SparseSolverKind::amg_pcg:
      return "amg";
  }
  return "?";
}

SparseSolverKind parse_sparse_solver(std::string_view name, std::string_view where) {
  for (const auto kind :
       {SparseSolverKind::automatic, SparseSolverKind::cholmod, SparseSolverKind::amg_pcg}) {
    if (name == to_string(kind)) return kind;
  }
  throw InputError(std::string(where), "unknown solver '" + std::string(name) + "'",
                   "use one of: auto, cholmod, amg");
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// ||f - K u|| / ||f|| (||f - K u|| if f = 0). Eigen runs the row-major product on OpenMP threads.
double relative_residual(const SparseMatrixRM& K, const Eigen::VectorXd& f,
                         const Eigen::VectorXd& u) {
  const double r = (f - K * u).norm();
  const double scale = f.norm();
  return scale > 0.0 ? r / scale : r;
}

std::string format_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// ---------------------------------------------------------------------------------------------
// CHOLMOD

SparseSolveReport solve_cholmod(const SparseMatrixRM& K, const Eigen::VectorXd& f,
                                Eigen::VectorXd& u) {
  const auto start = Clock::now();
  SparseSolveReport report;
  report.used = SparseSolverKind::cholmod;
  const CholmodFactor factor(K);
  factor.solve(f, u);
  report.peak_bytes = factor.peak_bytes();
  report.relative_residual = relative_residual(K, f, u);
  report.seconds = seconds_since(start);
  if (!std::isfinite(report.relative_residual)) throw_rigid_body_mode("cholmod");
  return report;
}

// ---------------------------------------------------------------------------------------------
// hypre BoomerAMG + PCG

/// BoomerAMG settings, measured with bench/sparse_solvers.cpp on clamped, top-loaded TBBM cubic
/// lattices (6 DOF, 45,600 and 156,600 unknowns) and on a generated random packing (15,455
/// particles, 86,802 unknowns), tolerance 1e-6:
/// - systems AMG, unknown-based (num_functions = block_size, nodal = 0): the packing needs 38
///   PCG iterations, 93 without num_functions; nodal coarsening (norms 1, 4, 6) took 13-65 % more
///   iterations and 20-60 % more time, as a block norm mixes force/m and moment/rad entries that
///   are ~r^2 apart;
/// - HMIS coarsening, ext+i interpolation (at most 4 entries a row), one level of aggressive
///   coarsening with multipass interpolation: without it the setup took 1.6-2x as long and the
///   lattices 1.5-1.7x overall (the packing: 26 instead of 38 iterations, 1.1x overall); 2-stage
///   ext+i on that level took 60 iterations on the packing;
/// - strong threshold 0.6: 0.5 to 0.8 were within the noise (20-22 iterations on the lattices,
///   38-41 on the packing); 0.25 took 27 on the lattice, 0.9 took 28;
/// - hypre's default smoother (l1-Gauss-Seidel forward down, backward up: symmetric, as PCG needs)
///   beat symmetric l1-GS (8) and hybrid symmetric GS (6), which save 1-6 iterations for a
///   costlier sweep (20-60 % slower overall); l1-Jacobi (18) took 180 iterations.
/// The lattices need 15-22 iterations from 1,080 to 374,400 unknowns.
void configure_boomeramg(HYPRE_Solver amg, HYPRE_Int n, int block_size) {
  HYPRE_BoomerAMGSetPrintLevel(amg, 0);
  HYPRE_BoomerAMGSetMaxIter(amg, 1);  // one V-cycle per PCG iteration
  HYPRE_BoomerAMGSetTol(amg, 0.0);
  HYPRE_BoomerAMGSetCoarsenType(amg, 10);  // HMIS
  HYPRE_BoomerAMGSetInterpType(amg, 6);    // extended+i
  HYPRE_BoomerAMGSetPMaxElmts(amg, 4);
  HYPRE_BoomerAMGSetAggNumLevels(amg, 1);
  HYPRE_BoomerAMGSetAggInterpType(amg, 4);  // multipass
  HYPRE_BoomerAMGSetStrongThreshold(amg, 0.6);
  if (block_size > 1 && n % block_size == 0) {
    HYPRE_BoomerAMGSetNumFunctions(amg, block_size);
    HYPRE_BoomerAMGSetNodal(amg, 0);
  }
}

/// K is lent to hypre (hypre::BorrowedMatrix) for the solve; u is hypre's iterate in place.
SparseSolveReport solve_amg_pcg(SparseMatrixRM& K, const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                const SparseSolverOptions& options) {
  hypre::start();
  const auto start = Clock::now();
  if (u.size() != K.rows()) u = Eigen::VectorXd::Zero(K.rows());
  Eigen::VectorXd b = f;  // hypre's right-hand side is not const (it is not written)
  const hypre::BorrowedMatrix A(K);
  const hypre::BorrowedVector par_b(b), par_x(u);

  hypre::BoomerAmg amg;
  hypre::check(HYPRE_BoomerAMGCreate(&amg.h), "HYPRE_BoomerAMGCreate");
  configure_boomeramg(amg.h, static_cast<HYPRE_Int>(K.rows()), options.block_size);
  hypre::ParCsrPcg pcg;
  hypre::check(HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &pcg.h), "HYPRE_ParCSRPCGCreate");
  HYPRE_PCGSetTol(pcg.h, options.tolerance);  // ||r|| <= tol ||f||
  HYPRE_PCGSetTwoNorm(pcg.h, 1);
  HYPRE_PCGSetMaxIter(pcg.h, options.max_iterations);
  HYPRE_PCGSetPrintLevel(pcg.h, 0);
  HYPRE_ParCSRPCGSetPrecond(pcg.h, HYPRE_BoomerAMGSolve, HYPRE_BoomerAMGSetup, amg.h);
  hypre::check(HYPRE_ParCSRPCGSetup(pcg.h, A.get(), par_b.get(), par_x.get()),
               "HYPRE_ParCSRPCGSetup");

  SparseSolveReport report;
  report.used = SparseSolverKind::amg_pcg;
  // PCG stops on its recursively updated residual, which can drift from the true one. If the true
  // residual misses the tolerance, go on from the current iterate (hypre's criterion is relative to
  // ||f||, not to the restart's residual).
  for (int attempt = 0; attempt < 3; ++attempt) {
    // A missed tolerance sets hypre's error flag; the true residual decides below.
    HYPRE_ParCSRPCGSolve(pcg.h, A.get(), par_b.get(), par_x.get());
    HYPRE_ClearAllErrors();
    HYPRE_Int iterations = 0;
    HYPRE_ParCSRPCGGetNumIterations(pcg.h, &iterations);
    report.iterations += iterations;
    // (K's rows are in hypre's order while lent; the product does not depend on it.)
    report.relative_residual = relative_residual(K, f, u);
    if (report.relative_residual <= options.tolerance || !std::isfinite(report.relative_residual) ||
        report.iterations >= options.max_iterations) {
      break;
    }
  }
  report.seconds = seconds_since(start);
  if (!(report.relative_residual <= options.tolerance)) {
    throw InputError("linear solve (amg)",
                     "AMG-PCG did not reach the tolerance " + format_number(options.tolerance) +
                         " in " + std::to_string(report.iterations) +
                         " iterations (relative residual " +
                         format_number(report.relative_residual) +
                         "); if K is singular, a rigid-body mode is unconstrained",
                     "use --solver cholmod, or a looser tolerance or more iterations; check that "
                     "enough degrees of freedom are fixed");
  }
  return report;
}

/// Checks the options and resolves `automatic` by K's size (cholmod or amg_pcg).
SparseSolverKind chosen_solver(const SparseMatrixRM& K, const SparseSolverOptions& options) {
  if (!(options.tolerance > 0.0) || options.max_iterations < 1 || options.block_size < 1) {
    throw InputError("linear solver options",
                     "tolerance and max_iterations must be positive and block_size at least 1");
  }
  if (options.kind != SparseSolverKind::automatic) return options.kind;
  return static_cast<std::size_t>(K.rows()) <= options.direct_limit ? SparseSolverKind::cholmod
                                                                    : SparseSolverKind::amg_pcg;
}

}  // namespace

SparseSolveReport solve_spd(SparseMatrixRM& K, const Eigen::VectorXd& f, Eigen::VectorXd& u,
                            const SparseSolverOptions& options) {
  if (K.rows() != K.cols() || f.size() != K.rows()) {
    throw std::invalid_argument("solve_spd: K is " + std::to_string(K.rows()) + "x" +
                                std::to_string(K.cols()) + ", f has " + std::to_string(f.size()) +
                                " entries");
  }
  const SparseSolverKind kind = chosen_solver(K, options);
  if (K.rows() == 0) {
    u.resize(0);
    SparseSolveReport empty;
    empty.used = kind;
    return empty;
  }
  K.makeCompressed();  // both solvers read K's arrays in place (compressed unless insert())
  if (kind == SparseSolverKind::cholmod) return solve_cholmod(K, f, u);
  return solve_amg_pcg(K, f, u, options);
}

// ---------------------------------------------------------------------------------------------
// SpdPreconditioner

/// K, lent to hypre, the BoomerAMG hierarchy set up on it, and the right-hand side and solution
/// vectors of every apply. Members are destroyed in reverse order: the solver first, K last.
struct SpdPreconditioner::Amg {
  SparseMatrixRM K;
  Eigen::VectorXd b, x;
  hypre::BorrowedMatrix A;
  hypre::BorrowedVector par_b, par_x;
  hypre::BoomerAmg amg;

  Amg(SparseMatrixRM&& matrix, int block_size)
      : K(std::move(matrix)),
        b(Eigen::VectorXd::Zero(K.rows())),
        x(Eigen::VectorXd::Zero(K.rows())),
        A(K),
        par_b(b),
        par_x(x) {
    hypre::check(HYPRE_BoomerAMGCreate(&amg.h), "HYPRE_BoomerAMGCreate");
    configure_boomeramg(amg.h, static_cast<HYPRE_Int>(K.rows()),
                        block_size);  // one V-cycle, tolerance 0
    hypre::check(HYPRE_BoomerAMGSetup(amg.h, A.get(), par_b.get(), par_x.get()),
                 "HYPRE_BoomerAMGSetup");
  }

  /// One V-cycle from z = 0 on K z = r: a fixed linear map of r.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    b = r;  // in place: hypre holds b's and x's arrays
    x.setZero();
    hypre::check(HYPRE_BoomerAMGSolve(amg.h, A.get(), par_b.get(), par_x.get()),
                 "HYPRE_BoomerAMGSolve");
    z = x;
  }
};

SpdPreconditioner::SpdPreconditioner(SparseMatrixRM K, const SparseSolverOptions& options)
    : kind_(chosen_solver(K, options)), size_(K.rows()) {
  if (K.rows() != K.cols()) {
    throw std::invalid_argument("SpdPreconditioner: K is " + std::to_string(K.rows()) + "x" +
                                std::to_string(K.cols()));
  }
  if (K.rows() == 0) return;
  K.makeCompressed();  // both read K's arrays in place
  if (kind_ == SparseSolverKind::cholmod) {
    cholmod_ = std::make_unique<CholmodFactor>(K);
  } else {
    amg_ = std::make_unique<Amg>(std::move(K), options.block_size);
  }
}

SpdPreconditioner::~SpdPreconditioner() = default;

SparseSolverKind SpdPreconditioner::kind() const {
  return kind_;
}

void SpdPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (r.size() != size_) {
    throw std::invalid_argument("SpdPreconditioner::apply: r has " + std::to_string(r.size()) +
                                " entries, K " + std::to_string(size_) + " rows");
  }
  if (size_ == 0) {
    z.resize(0);
  } else if (cholmod_) {
    cholmod_->solve(r, z);
  } else {
    amg_->apply(r, z);
  }
}

}  // namespace bpm
