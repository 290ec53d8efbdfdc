#pragma once
/// The DSM's linear solves across the ranks of an mpirun (issue 14), for samples whose K does not
/// fit one machine. Each rank holds the rows of K of one contiguous range of particles; hypre's IJ
/// interface builds the distributed ParCSR matrix, and BoomerAMG (its own V-cycle, run across the
/// ranks) preconditions conjugate gradients.
///
/// The vectors stay whole on every rank: a product or a V-cycle computes this rank's rows and one
/// MPI_Allgatherv makes the whole vector again, so the rest of the DSM (platen springs, contact
/// corrections, Newton's method, the deflation of the rigid modes) is the one-process code, run
/// on identical data on every rank. The matrix and the multigrid hierarchy, nearly all of the
/// memory, are divided; the vectors (dofs N doubles each) are not. On one process
/// ShiftedSpdSolver runs instead, with the threaded V-cycle (amg_vcycle.hpp).
#include <cstdint>
#include <memory>
#include <vector>

#include "solvers/sparse_solver.hpp"

namespace bpm {

class DistributedAmg;

/// Contiguous ranges of particles, one per part, with about equal sums of `weight` (K's row block
/// of a particle: 1 + its partners, so about equal shares of K's entries). The particle store is in
/// the canonical space-filling-curve order (model/spatial_order.hpp), so each range is a compact
/// piece of the sample and its halo (partners in other ranges) is its surface. Returns parts + 1
/// boundaries: the first particle of each part, then the particle count.
std::vector<std::size_t> partition_particles(const std::vector<std::size_t>& weight, int parts);

/// The whole vector on every rank (MPI_Allgatherv) from each rank's rows: this rank's are
/// rows[0, row_start[rank + 1] - row_start[rank]).
void gather_rows(const double* rows, const std::vector<int>& row_start, Eigen::VectorXd& whole);

class DistributedShiftedSolver final : public ShiftedSystem {
 public:
  /// K_rows: this rank's rows of K (rows row_start[rank] to row_start[rank + 1] - 1, every column;
  /// statics/static_assembly.hpp: ParticleRange), taken over (swapped). row_start: every rank's
  /// first row, then K's size, the same on every rank. Collective over MPI_COMM_WORLD, like every
  /// member.
  DistributedShiftedSolver(SparseMatrixRM&& K_rows, std::vector<int> row_start,
                           const SparseSolverOptions& options);
  ~DistributedShiftedSolver() override;
  DistributedShiftedSolver(const DistributedShiftedSolver&) = delete;
  DistributedShiftedSolver& operator=(const DistributedShiftedSolver&) = delete;

  /// As ShiftedSpdSolver::solve; the first builds BoomerAMG's hierarchy of K + diag(shift).
  SparseSolveReport solve(const Eigen::VectorXd& shift, const Eigen::VectorXd& f,
                          Eigen::VectorXd& u, double tolerance,
                          const AddedProduct* added = nullptr) override;
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  void set_coarse_space(Eigen::MatrixXd Z) override;
  SparseSolverKind kind() const override { return SparseSolverKind::amg_pcg; }

  /// The whole vector, on every rank, from each rank's rows (`rows`: this rank's).
  void gather(const Eigen::VectorXd& rows, Eigen::VectorXd& whole) const;
  /// K's stored entries on all ranks together.
  std::size_t nonzeros() const;

 private:
  void set_up(const Eigen::VectorXd& shift);
  Eigen::Index first_row() const;
  Eigen::Index local_rows() const;
  /// y = (K + diag(shift_)) x: this rank's rows, then gathered (shift_ is zero before the set-up).
  void multiply_held(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

  SparseSolverOptions options_;
  std::vector<int> row_start_;
  int rank_ = 0;
  std::size_t nonzeros_ = 0;   ///< K's entries on all ranks
  SparseMatrixRM K_;           ///< this rank's rows until the set-up hands them to hypre
  std::vector<int> diagonal_;  ///< index of each local row's diagonal entry in K_'s values
  std::vector<double> base_;   ///< K's diagonal on this rank's rows
  Eigen::VectorXd shift_;      ///< the shift hypre's matrix and hierarchy hold (whole)
  std::unique_ptr<DistributedAmg> amg_;
  Eigen::MatrixXd Z_, KZ_;  ///< the coarse space and K Z (whole)
};

}  // namespace bpm
