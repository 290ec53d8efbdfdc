#pragma once
/// Solvers for the symmetric positive definite systems K u = f of the direct stiffness method
/// (Jarolin section 3.1, Eq. 9): a sparse direct Cholesky factorisation (SuiteSparse CHOLMOD) for
/// small and medium systems, and conjugate gradients preconditioned with algebraic multigrid (hypre
/// BoomerAMG) for large ones. `automatic` picks by size; the user can override it.
#include <Eigen/SparseCore>
#include <cstddef>
#include <string_view>

namespace bpm {

enum class SparseSolverKind { automatic, cholmod, amg_pcg };

/// "auto", "cholmod", "amg" <-> kind; parse throws InputError naming `where` and the valid names.
std::string_view to_string(SparseSolverKind kind);
SparseSolverKind parse_sparse_solver(std::string_view name, std::string_view where);

struct SparseSolverOptions {
  SparseSolverKind kind = SparseSolverKind::automatic;
  /// Iterative solvers stop at ||f - K u|| <= tolerance ||f|| (Jarolin: 1e-6).
  double tolerance = 1e-6;
  int max_iterations = 2000;
  /// `automatic` uses CHOLMOD up to this many unknowns and AMG-PCG above.
  std::size_t direct_limit = 200000;
  /// Unknowns per node (6: translation + rotation, 3: translation only); lets AMG treat the
  /// unknowns of one particle as a block (hypre's systems AMG, num_functions).
  int block_size = 6;
};

struct SparseSolveReport {
  SparseSolverKind used = SparseSolverKind::cholmod;
  int iterations = 0;              ///< 0 for the direct solver
  double relative_residual = 0.0;  ///< ||f - K u|| / ||f||, computed after the solve
  double seconds = 0.0;            ///< setup + solve, wall clock
  std::size_t peak_bytes = 0;      ///< CHOLMOD's peak memory (its own count); 0 for AMG-PCG
};

/// Solves K u = f. K is symmetric positive definite, stored in full (both triangles), row-major
/// compressed (Eigen's RowMajor SparseMatrix with int indices). u holds the initial guess on entry
/// for the iterative solver (zero if its size does not match). Throws InputError if K is singular or
/// not positive definite (a rigid-body mode left free) or the iteration does not reach the tolerance.
using SparseMatrixRM = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
SparseSolveReport solve_spd(const SparseMatrixRM& K, const Eigen::VectorXd& f, Eigen::VectorXd& u,
                            const SparseSolverOptions& options = {});

}  // namespace bpm
