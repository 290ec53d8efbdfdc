#include "dsm/distributed_solver.hpp"

#include <HYPRE_IJ_mv.h>
#include <_hypre_parcsr_ls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "dsm/amg_vcycle.hpp"
#include "dsm/hypre_support.hpp"

namespace bpm {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double* local_data(HYPRE_ParVector v) {
  return hypre_VectorData(hypre_ParVectorLocalVector(reinterpret_cast<hypre_ParVector*>(v)));
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

/// hypre's objects of the distributed solve: K + diag(shift) as an IJ (ParCSR) matrix, the
/// right-hand side and solution of a V-cycle, and the BoomerAMG hierarchy.
struct DistributedShiftedSolver::Hypre {
  HYPRE_IJMatrix matrix = nullptr;
  HYPRE_IJVector rhs = nullptr, solution = nullptr;
  HYPRE_ParCSRMatrix A = nullptr;
  HYPRE_ParVector b = nullptr, x = nullptr;
  hypre::BoomerAmg amg;
  int levels = 0;
  ~Hypre() {
    if (matrix) HYPRE_IJMatrixDestroy(matrix);
    if (rhs) HYPRE_IJVectorDestroy(rhs);
    if (solution) HYPRE_IJVectorDestroy(solution);
  }
};

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
    if (diagonal_[i] < 0)
      throw std::invalid_argument("DistributedShiftedSolver: row " + std::to_string(global) +
                                  " has no diagonal entry");
    base_[i] = K_.valuePtr()[diagonal_[i]];
  }
  auto own = static_cast<long long>(K_.nonZeros()), all = 0LL;
  MPI_Allreduce(&own, &all, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  nonzeros_ = static_cast<std::size_t>(all);
}

DistributedShiftedSolver::~DistributedShiftedSolver() = default;

void DistributedShiftedSolver::gather(const Eigen::VectorXd& rows, Eigen::VectorXd& whole) const {
  const std::size_t ranks = row_start_.size() - 1;
  std::vector<int> counts(ranks);
  for (std::size_t k = 0; k < ranks; ++k) counts[k] = row_start_[k + 1] - row_start_[k];
  whole.resize(row_start_.back());
  MPI_Allgatherv(rows.data(), static_cast<int>(rows.size()), MPI_DOUBLE, whole.data(),
                 counts.data(), row_start_.data(), MPI_DOUBLE, MPI_COMM_WORLD);
}

std::size_t DistributedShiftedSolver::nonzeros() const {
  return nonzeros_;
}

void DistributedShiftedSolver::multiply_held(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  if (!hypre_) {  // before the set-up: this rank's rows in Eigen (Eigen's product on the threads)
    const Eigen::VectorXd rows = K_ * x;
    gather(rows, y);
    return;
  }
  // After it K lives in hypre's matrix alone: its product (with its own halo exchange) on this
  // rank's part of x, through the V-cycle's vectors (not in use between cycles).
  const Hypre& h = *hypre_;
  const auto first = row_start_[static_cast<std::size_t>(rank_)];
  const Eigen::Index rows = row_start_[static_cast<std::size_t>(rank_) + 1] - first;
  Eigen::Map<Eigen::VectorXd>(local_data(h.b), rows) = x.segment(first, rows);
  hypre::check(HYPRE_ParCSRMatrixMatvec(1.0, h.A, h.b, 0.0, h.x), "HYPRE_ParCSRMatrixMatvec");
  gather(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(local_data(h.x), rows)), y);
}

void DistributedShiftedSolver::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  multiply_held(x, y);
  if (shift_.size() == x.size()) y -= shift_.cwiseProduct(x);
}

void DistributedShiftedSolver::set_coarse_space(Eigen::MatrixXd Z) {
  if (Z.cols() > 0 && Z.rows() != row_start_.back())
    throw std::invalid_argument("DistributedShiftedSolver::set_coarse_space: Z has the wrong rows");
  Z_ = std::move(Z);
  KZ_.resize(Z_.rows(), Z_.cols());
  Eigen::VectorXd column;
  for (Eigen::Index k = 0; k < Z_.cols(); ++k) {
    multiply(Z_.col(k), column);
    KZ_.col(k) = column;
  }
}

void DistributedShiftedSolver::set_up(const Eigen::VectorXd& shift) {
  const auto r = static_cast<std::size_t>(rank_);
  const int first = row_start_[r], last = row_start_[r + 1] - 1;
  const auto rows = static_cast<int>(K_.rows());
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  double* value = K_.valuePtr();
  for (int i = 0; i < rows; ++i)
    value[diagonal_[static_cast<std::size_t>(i)]] =
        base_[static_cast<std::size_t>(i)] + shift[first + i];
  shift_ = shift;

  hypre_ = std::make_unique<Hypre>();
  Hypre& h = *hypre_;
  hypre::check(HYPRE_IJMatrixCreate(MPI_COMM_WORLD, first, last, first, last, &h.matrix),
               "HYPRE_IJMatrixCreate");
  hypre::check(HYPRE_IJMatrixSetObjectType(h.matrix, HYPRE_PARCSR), "HYPRE_IJMatrixSetObjectType");
  // Each row's entries in this rank's columns and in others' (the halo), so hypre allocates once.
  std::vector<HYPRE_Int> own(static_cast<std::size_t>(rows)), other(static_cast<std::size_t>(rows)),
      length(static_cast<std::size_t>(rows));
  std::vector<HYPRE_BigInt> row_ids(static_cast<std::size_t>(rows));
  for (int i = 0; i < rows; ++i) {
    const auto at = static_cast<std::size_t>(i);
    for (int e = outer[i]; e < outer[i + 1]; ++e)
      ++(inner[e] >= first && inner[e] <= last ? own[at] : other[at]);
    length[at] = outer[i + 1] - outer[i];
    row_ids[at] = first + i;
  }
  hypre::check(HYPRE_IJMatrixSetDiagOffdSizes(h.matrix, own.data(), other.data()),
               "HYPRE_IJMatrixSetDiagOffdSizes");
  hypre::check(HYPRE_IJMatrixInitialize(h.matrix), "HYPRE_IJMatrixInitialize");
  hypre::check(HYPRE_IJMatrixSetValues(h.matrix, rows, length.data(), row_ids.data(), inner, value),
               "HYPRE_IJMatrixSetValues");
  hypre::check(HYPRE_IJMatrixAssemble(h.matrix), "HYPRE_IJMatrixAssemble");
  hypre::check(HYPRE_IJMatrixGetObject(h.matrix, reinterpret_cast<void**>(&h.A)),
               "HYPRE_IJMatrixGetObject");
  SparseMatrixRM().swap(K_);  // hypre's copy serves the products from now on: a copy less per rank
  for (auto [vector, object] : {std::pair{&h.rhs, &h.b}, std::pair{&h.solution, &h.x}}) {
    hypre::check(HYPRE_IJVectorCreate(MPI_COMM_WORLD, first, last, vector), "HYPRE_IJVectorCreate");
    hypre::check(HYPRE_IJVectorSetObjectType(*vector, HYPRE_PARCSR), "HYPRE_IJVectorSetObjectType");
    hypre::check(HYPRE_IJVectorInitialize(*vector), "HYPRE_IJVectorInitialize");
    hypre::check(HYPRE_IJVectorAssemble(*vector), "HYPRE_IJVectorAssemble");
    hypre::check(HYPRE_IJVectorGetObject(*vector, reinterpret_cast<void**>(object)),
                 "HYPRE_IJVectorGetObject");
  }

  hypre::check(HYPRE_BoomerAMGCreate(&h.amg.h), "HYPRE_BoomerAMGCreate");
  hypre::configure_boomeramg(h.amg.h, row_start_.back(), options_.block_size,
                             options_.nodal_coarsening);
  // hypre's own cycle across the ranks, one V-cycle from zero as CG's preconditioner: symmetric
  // hybrid Gauss-Seidel (relaxation type 6: Gauss-Seidel within a rank, Jacobi between ranks,
  // forward down and backward up, so the cycle is a symmetric map) and Gaussian elimination on the
  // coarsest level. On the 1e5-particle cylinder, 2 ranks, --tolerance 1e-6 (2026-12-04): type 6
  // took 44 + 13 CG iterations and 14.5 s, Chebyshev (16) 50 + 15 and 15.6 s, l1-scaled symmetric
  // Gauss-Seidel (8) 303 + 60, l1-Jacobi (18) 1149 + 314.
  HYPRE_BoomerAMGSetRelaxType(h.amg.h, 6);
  HYPRE_BoomerAMGSetCycleRelaxType(h.amg.h, 9, 3);
  HYPRE_BoomerAMGSetNumSweeps(h.amg.h, 1);
  HYPRE_BoomerAMGSetTol(h.amg.h, 0.0);
  HYPRE_BoomerAMGSetMaxIter(h.amg.h, 1);
  hypre::check(HYPRE_BoomerAMGSetup(h.amg.h, h.A, h.b, h.x), "HYPRE_BoomerAMGSetup");
  h.levels = hypre_ParAMGDataNumLevels(reinterpret_cast<hypre_ParAMGData*>(h.amg.h));
}

void DistributedShiftedSolver::precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const Hypre& h = *hypre_;
  const auto first = row_start_[static_cast<std::size_t>(rank_)];
  const Eigen::Index rows = row_start_[static_cast<std::size_t>(rank_) + 1] - first;
  Eigen::Map<Eigen::VectorXd>(local_data(h.b), rows) = r.segment(first, rows);
  Eigen::Map<Eigen::VectorXd> x(local_data(h.x), rows);
  x.setZero();
  // One V-cycle: with MaxIter 1 and Tol 0 hypre reports "not converged", which is expected here.
  HYPRE_BoomerAMGSolve(h.amg.h, h.A, h.b, h.x);
  HYPRE_ClearAllErrors();
  gather(Eigen::VectorXd(x), z);
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
  if (!hypre_) {
    set_up(shift);
    report.levels = hypre_->levels;
    report.setup_seconds = seconds_since(start);
  }
  // The operator: hypre's matrix (which holds shift_) plus the rest of the shift and `added`.
  const Eigen::VectorXd extra = shift - shift_;
  const LinearOperator A = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    multiply_held(x, y);
    y.array() += extra.array() * x.array();
    if (added) (*added)(x.data(), y.data());
  };
  Eigen::MatrixXd AZ;
  if (Z_.cols() > 0) {
    AZ = KZ_ + shift.asDiagonal() * Z_;
    if (added) {
      for (Eigen::Index k = 0; k < Z_.cols(); ++k) (*added)(Z_.col(k).data(), AZ.col(k).data());
    }
  }
  const CoarseCorrection coarse(Z_, std::move(AZ));
  const Preconditioner M = [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    precondition(r, z);
  };
  // As one process does (sparse_solver.cpp): CG stops on its recursive residual; go on from the
  // iterate, twice at most, until the true one meets the tolerance.
  Eigen::VectorXd Au;
  const double scale = f.norm() > 0.0 ? f.norm() : 1.0;
  for (int attempt = 0; attempt < 3; ++attempt) {
    report.iterations += preconditioned_conjugate_gradients(
        A, M, f, u, tolerance, options_.max_iterations - report.iterations, &coarse);
    A(u, Au);
    report.relative_residual = (f - Au).norm() / scale;
    if (report.relative_residual <= tolerance || !std::isfinite(report.relative_residual) ||
        report.iterations >= options_.max_iterations) {
      break;
    }
  }
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
