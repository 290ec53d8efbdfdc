#include "solvers/distributed_solver.hpp"

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "solvers/amg_vcycle.hpp"
#include "solvers/distributed_amg.hpp"
#include "solvers/hypre_support.hpp"

namespace bpm {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

std::vector<std::size_t> partition_particles(const std::vector<std::size_t>& weight, int parts) {
  if (parts < 1) throw std::invalid_argument("partition_particles: parts must be at least 1");
  const double total =
      static_cast<double>(std::accumulate(weight.begin(), weight.end(), std::size_t{0}));
  std::vector<std::size_t> start(static_cast<std::size_t>(parts) + 1, weight.size());
  start[0] = 0;
  // Part k ends where the running sum first reaches k / parts of the total.
  double sum = 0.0;
  int part = 1;
  for (std::size_t q = 0; q < weight.size() && part < parts; ++q) {
    sum += static_cast<double>(weight[q]);
    while (part < parts && sum >= total * part / parts)
      start[static_cast<std::size_t>(part++)] = q + 1;
  }
  return start;
}

void gather_rows(const double* rows, const std::vector<int>& row_start, Eigen::VectorXd& whole) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::size_t ranks = row_start.size() - 1;
  std::vector<int> counts(ranks);
  for (std::size_t k = 0; k < ranks; ++k) counts[k] = row_start[k + 1] - row_start[k];
  whole.resize(row_start.back());
  MPI_Allgatherv(rows, counts[static_cast<std::size_t>(rank)], MPI_DOUBLE, whole.data(),
                 counts.data(), row_start.data(), MPI_DOUBLE, MPI_COMM_WORLD);
}

DistributedShiftedSolver::DistributedShiftedSolver(SparseMatrixRM&& K_rows,
                                                   std::vector<int> row_start,
                                                   const SparseSolverOptions& options)
    : options_(options), row_start_(std::move(row_start)) {
  hypre::start();
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const auto r = static_cast<std::size_t>(rank_);
  if (row_start_.size() != static_cast<std::size_t>(size) + 1 ||
      K_rows.rows() != row_start_[r + 1] - row_start_[r] || K_rows.cols() != row_start_.back()) {
    throw std::invalid_argument("DistributedShiftedSolver: K's rows do not match the partition");
  }
  K_.swap(K_rows);  // Eigen 3.4's SparseMatrix has no move constructor
  K_.makeCompressed();
  const auto rows = static_cast<std::size_t>(K_.rows());
  diagonal_.assign(rows, -1);
  base_.assign(rows, 0.0);
  for (std::size_t i = 0; i < rows; ++i) {
    const int global = row_start_[r] + static_cast<int>(i);
    for (int e = K_.outerIndexPtr()[i]; e < K_.outerIndexPtr()[i + 1]; ++e) {
      if (K_.innerIndexPtr()[e] == global) diagonal_[i] = e;
    }
    if (diagonal_[i] < 0) {
      throw std::invalid_argument("DistributedShiftedSolver: row " + std::to_string(global) +
                                  " has no diagonal entry");
    }
    base_[i] = K_.valuePtr()[diagonal_[i]];
  }
  auto own = static_cast<long long>(K_.nonZeros()), all = 0LL;
  MPI_Allreduce(&own, &all, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  nonzeros_ = static_cast<std::size_t>(all);
}

DistributedShiftedSolver::~DistributedShiftedSolver() = default;

Eigen::Index DistributedShiftedSolver::first_row() const {
  return row_start_[static_cast<std::size_t>(rank_)];
}

Eigen::Index DistributedShiftedSolver::local_rows() const {
  return row_start_[static_cast<std::size_t>(rank_) + 1] - first_row();
}

void DistributedShiftedSolver::gather(const Eigen::VectorXd& rows, Eigen::VectorXd& whole) const {
  gather_rows(rows.data(), row_start_, whole);
}

std::size_t DistributedShiftedSolver::nonzeros() const {
  return nonzeros_;
}

void DistributedShiftedSolver::multiply_held(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  Eigen::VectorXd rows(local_rows());
  if (amg_) {
    amg_->multiply(x.data() + first_row(), rows.data());  // K lives in hypre's matrix alone now
  } else {
    rows = K_ * x;  // before the set-up: this rank's rows in Eigen
  }
  gather(rows, y);
}

void DistributedShiftedSolver::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  multiply_held(x, y);
  if (shift_.size() == x.size()) y -= shift_.cwiseProduct(x);
}

void DistributedShiftedSolver::set_coarse_space(Eigen::MatrixXd Z) {
  if (Z.cols() > 0 && Z.rows() != row_start_.back()) {
    throw std::invalid_argument("DistributedShiftedSolver::set_coarse_space: Z has the wrong rows");
  }
  Z_ = std::move(Z);
  KZ_.resize(Z_.rows(), Z_.cols());
  Eigen::VectorXd column;
  for (Eigen::Index k = 0; k < Z_.cols(); ++k) {
    multiply(Z_.col(k), column);
    KZ_.col(k) = column;
  }
}

void DistributedShiftedSolver::set_up(const Eigen::VectorXd& shift) {
  double* value = K_.valuePtr();
  for (Eigen::Index i = 0; i < local_rows(); ++i) {
    const auto at = static_cast<std::size_t>(i);
    value[diagonal_[at]] = base_[at] + shift[first_row() + i];
  }
  shift_ = shift;
  amg_ = std::make_unique<DistributedAmg>(K_, row_start_, options_);  // empties K_: hypre holds it
}

void DistributedShiftedSolver::precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  Eigen::VectorXd rows(local_rows());
  amg_->apply(r.data() + first_row(), rows.data());
  gather(rows, z);
}

SparseSolveReport DistributedShiftedSolver::solve(const Eigen::VectorXd& shift,
                                                  const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                                  double tolerance, const AddedProduct* added) {
  const auto start = Clock::now();
  const Eigen::Index n = row_start_.back();
  if (shift.size() != n || f.size() != n)
    throw std::invalid_argument("DistributedShiftedSolver::solve: sizes differ");
  SparseSolveReport report;
  report.used = SparseSolverKind::amg_pcg;
  if (!amg_) {
    set_up(shift);
    report.levels = amg_->levels();
    report.setup_seconds = seconds_since(start);
  }
  // The operator: hypre's matrix (which holds shift_) plus the rest of the shift and `added`.
  const Eigen::VectorXd extra = shift - shift_;
  const LinearOperator A = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    multiply_held(x, y);
    y.array() += extra.array() * x.array();
    if (added) (*added)(x.data(), y.data());
  };
  const CoarseCorrection coarse(Z_, shifted_coarse_product(Z_, KZ_, shift, added));
  const Preconditioner M = [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    precondition(r, z);
  };
  Eigen::VectorXd Au;
  const double scale = f.norm() > 0.0 ? f.norm() : 1.0;
  conjugate_gradients_to_tolerance(
      [&](int iterations) {
        return preconditioned_conjugate_gradients(A, M, f, u, tolerance, iterations, &coarse);
      },
      [&] {
        A(u, Au);
        return (f - Au).norm() / scale;
      },
      tolerance, options_.max_iterations, report);
  report.seconds = seconds_since(start);
  if (!(report.relative_residual <= tolerance)) {
    char residual[32];
    std::snprintf(residual, sizeof residual, "%.3g", report.relative_residual);
    throw InputError("linear solve (amg, " + std::to_string(row_start_.size() - 1) + " MPI ranks)",
                     "conjugate gradients did not reach the tolerance in " +
                         std::to_string(report.iterations) + " iterations (relative residual " +
                         residual + ")",
                     "use more iterations; check that the platens touch the sample");
  }
  return report;
}

}  // namespace bpm
