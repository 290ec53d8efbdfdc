#pragma once
/// Algebraic multigrid V-cycle for the DSM's SPD systems, run on all OpenMP threads. hypre's
/// BoomerAMG builds the hierarchy (coarsening, interpolation P, Galerkin coarse operators
/// P^T A P), which runs on one core in Debian's serial hypre build; the cycle itself, applied once
/// per CG iteration, is ours and threaded: Chebyshev smoothing of degree 2 on D^-1 A (Adams et al.
/// 2003, "Parallel multigrid smoothing: polynomial versus Gauss-Seidel"), restriction P^T,
/// interpolation P, and CHOLMOD on the coarsest level. Gauss-Seidel, hypre's own smoother, is
/// sequential by nature; the polynomial smoother needs only matrix-vector products, so its result
/// does not depend on the number of threads.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "solvers/sparse_solver.hpp"

namespace bpm {

template <typename Value>
class BlockCsr;
class CholmodFactor;

class AmgVCycle {
 public:
  /// Builds the hierarchy of K (symmetric positive definite, full storage, compressed; lent to
  /// hypre during the set-up, then handed back unchanged). K itself is the finest level: it must
  /// outlive this object and not change. block_size: unknowns per node (hypre's systems AMG).
  /// If K is made of block_size x block_size blocks (block_csr.hpp), the cycle keeps K in blocks,
  /// in double for conjugate gradients' products with K and rounded to float for its own (0.72
  /// and 0.36 times the memory of K's CSR arrays on the 1e5 cylinder; the float copy replaces the
  /// CSR one, 0.33).
  /// nodal: hypre coarsens by particle (its nodal coarsening 1, the Frobenius norm of each
  /// block_size x block_size block as the strength) instead of by unknown; see configure_boomeramg.
  AmgVCycle(SparseMatrixRM& K, int block_size, bool nodal = false);
  ~AmgVCycle();
  AmgVCycle(const AmgVCycle&) = delete;
  AmgVCycle& operator=(const AmgVCycle&) = delete;

  /// z = one V-cycle from zero on K z = r: a fixed, symmetric linear map of r (the same Chebyshev
  /// polynomial before and after the coarse correction), as conjugate gradients needs.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z);

  int levels() const;
  /// K in blocks (block_csr.hpp), or null if K is not block-structured: conjugate gradients on K
  /// reads it instead of K (the same products, less memory traffic).
  const BlockCsr<double>* blocks() const;

 private:
  struct Level;
  void cycle(std::size_t level);
  std::vector<std::unique_ptr<Level>> levels_;
  std::unique_ptr<CholmodFactor> coarsest_;
  std::unique_ptr<BlockCsr<double>> finest_blocks_;  ///< K in blocks: the cycle's and CG's
};

/// A symmetric positive definite approximate inverse: z = M r (z is resized).
using Preconditioner = std::function<void(const Eigen::VectorXd& r, Eigen::VectorXd& z)>;

/// An exact correction on the span of a few vectors Z (n x m, m small) that the preconditioner
/// represents badly, for conjugate gradients: deflation in the form A-DEF2 of Tang, Nabben, Vuik
/// and Erlangga (2009, J. Sci. Comput. 39, "Comparison of two-level preconditioners derived from
/// deflation, domain decomposition and multigrid methods"). With E = Z^T A Z, CG starts from
/// u + Z E^-1 Z^T r, and each preconditioned residual z becomes z - Z E^-1 (AZ)^T z: the search
/// directions stay A-orthogonal to Z, whose part of the error the start removed. Two passes over
/// Z and AZ an iteration; sums over fixed blocks of rows, so the result does not depend on the
/// number of threads.
class CoarseCorrection {
 public:
  /// AZ = A Z for the operator A of the solve. Empty (no correction) if Z has no columns or
  /// Z^T A Z is not positive definite.
  CoarseCorrection(const Eigen::MatrixXd& Z, Eigen::MatrixXd AZ);
  bool empty() const { return inverse_.size() == 0; }
  /// u += Z E^-1 Z^T r and r -= AZ E^-1 Z^T r (r = f - A u before and after).
  void start(Eigen::VectorXd& u, Eigen::VectorXd& r) const;
  /// z -= Z E^-1 (AZ)^T z.
  void project(Eigen::VectorXd& z) const;

 private:
  const Eigen::MatrixXd& Z_;
  Eigen::MatrixXd AZ_;
  Eigen::MatrixXd inverse_;  ///< E^-1 (m x m)
};

/// Conjugate gradients on K u = f preconditioned by `M` (one V-cycle, or an exact factor of a
/// nearby matrix), from the u given (zero if its size does not match), until
/// ||f - K u|| <= tolerance ||f|| (the recursive residual; the caller checks the true one). Returns
/// the iterations. Products and vector updates run on all threads; dot products sum fixed blocks
/// in a fixed order, so u is the same for any number of threads. With `shift`, the operator is
/// K + diag(shift), plus `added` if given. With `blocks` (K in blocks: AmgVCycle::blocks), the
/// products read them instead of K's CSR arrays. With `coarse`, deflated by it (CoarseCorrection).
int preconditioned_conjugate_gradients(const SparseMatrixRM& K, const Preconditioner& M,
                                       const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                       double tolerance, int max_iterations,
                                       const Eigen::VectorXd* shift = nullptr,
                                       const BlockCsr<double>* blocks = nullptr,
                                       const AddedProduct* added = nullptr,
                                       const CoarseCorrection* coarse = nullptr);

/// A Z for the operator A = K + diag(shift) + added of a solve, from KZ = K Z: the coarse space's
/// image that CoarseCorrection needs (ShiftedSpdSolver, DistributedShiftedSolver).
Eigen::MatrixXd shifted_coarse_product(const Eigen::MatrixXd& Z, const Eigen::MatrixXd& KZ,
                                       const Eigen::VectorXd& shift, const AddedProduct* added);

/// Runs conjugate gradients until the true relative residual meets the tolerance: `cg` iterates
/// from the current iterate with the iterations it is given and returns those it took, stopping on
/// its recursive residual, which can drift from the true one; `true_residual` recomputes
/// ||f - A u|| / ||f||. So CG goes on from its iterate, twice at most. Adds the iterations and the
/// residual to `report`.
void conjugate_gradients_to_tolerance(const std::function<int(int)>& cg,
                                      const std::function<double()>& true_residual,
                                      double tolerance, int max_iterations,
                                      SparseSolveReport& report);

/// y = A x (y is resized) for a symmetric positive definite operator A.
using LinearOperator = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& y)>;
/// The same iteration on an operator given by its product (the one above calls it): the
/// distributed DSM's, whose product is each rank's rows of K gathered (distributed_solver.hpp).
int preconditioned_conjugate_gradients(const LinearOperator& A, const Preconditioner& M,
                                       const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                       double tolerance, int max_iterations,
                                       const CoarseCorrection* coarse = nullptr);

}  // namespace bpm
