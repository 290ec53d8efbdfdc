#pragma once
/// A matrix divided by rows between the ranks of an mpirun, in hypre's ParCSR format, with
/// BoomerAMG's hierarchy of it: its product and one V-cycle, on this rank's rows of the vectors.
/// The preconditioner of the DSM's solves across ranks: the linear DSM's conjugate gradients
/// (distributed_solver.hpp) and the nonlinear DSM's GMRES (dsm_nonlinear.cpp).
#include <memory>
#include <vector>

#include "solvers/sparse_solver.hpp"

namespace bpm {

class DistributedAmg {
 public:
  /// rows: this rank's rows of an SPD matrix A (rows row_start[rank] to row_start[rank + 1] - 1,
  /// every column, each row's diagonal stored), copied into hypre and then emptied, before the
  /// hierarchy is built (on case 3 that kept 1.3 GB per rank off the peak); row_start: every rank's
  /// first row, then A's size, the same on every rank. Builds the hierarchy with the one-process
  /// settings (hypre::configure_boomeramg; block_size and nodal_coarsening of `options`).
  /// Collective over MPI_COMM_WORLD, like every member.
  DistributedAmg(SparseMatrixRM& rows, const std::vector<int>& row_start,
                 const SparseSolverOptions& options);
  ~DistributedAmg();
  DistributedAmg(const DistributedAmg&) = delete;
  DistributedAmg& operator=(const DistributedAmg&) = delete;

  /// z = one V-cycle from zero on A z = r (this rank's rows of r and z): a fixed symmetric map.
  void apply(const double* r, double* z) const;
  /// y = A x (this rank's rows; hypre exchanges the halo of x).
  void multiply(const double* x, double* y) const;
  int levels() const;

 private:
  struct Hypre;
  std::unique_ptr<Hypre> hypre_;
  int rows_ = 0;
};

}  // namespace bpm
