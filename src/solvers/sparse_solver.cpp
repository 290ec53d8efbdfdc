#include "solvers/sparse_solver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "solvers/amg_vcycle.hpp"
#include "solvers/block_csr.hpp"
#include "solvers/cholmod_factor.hpp"
#include "solvers/hypre_support.hpp"

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

/// ||f - (K + diag(shift) + added) u|| / ||f|| (the numerator if f = 0). K's product reads its
/// blocks if given, else Eigen's row-major product (both on OpenMP threads).
double relative_residual(const SparseMatrixRM& K, const Eigen::VectorXd& f,
                         const Eigen::VectorXd& u, const Eigen::VectorXd* shift = nullptr,
                         const AddedProduct* added = nullptr,
                         const BlockCsr<double>* blocks = nullptr) {
  Eigen::VectorXd Au(K.rows());
  if (blocks)
    blocks->multiply(u.data(), Au.data());  // the same sums, fewer bytes
  else
    Au = K * u;
  if (shift) Au += shift->cwiseProduct(u);
  if (added) (*added)(u.data(), Au.data());
  const double r = (f - Au).norm();
  const double scale = f.norm();
  return scale > 0.0 ? r / scale : r;
}

/// Preconditioned CG on (K + diag(shift) + added) u = f until the true relative residual meets
/// the tolerance (amg_vcycle.hpp: conjugate_gradients_to_tolerance).
void conjugate_gradients_to_tolerance(const SparseMatrixRM& K, const Preconditioner& M,
                                      const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                      double tolerance, int max_iterations,
                                      const Eigen::VectorXd* shift, SparseSolveReport& report,
                                      const BlockCsr<double>* blocks = nullptr,
                                      const AddedProduct* added = nullptr,
                                      const CoarseCorrection* coarse = nullptr) {
  conjugate_gradients_to_tolerance(
      [&](int iterations) {
        return preconditioned_conjugate_gradients(K, M, f, u, tolerance, iterations, shift, blocks,
                                                  added, coarse);
      },
      [&] { return relative_residual(K, f, u, shift, added, blocks); }, tolerance, max_iterations,
      report);
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
// AMG-PCG

/// Conjugate gradients preconditioned with one V-cycle of AmgVCycle (hierarchy from hypre, cycle on
/// all threads). K is lent to hypre for the set-up.
SparseSolveReport solve_amg_pcg(SparseMatrixRM& K, const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                const SparseSolverOptions& options) {
  hypre::start();  // MPI's one-time start is not part of the solve
  const auto start = Clock::now();
  AmgVCycle cycle(K, options.block_size);
  SparseSolveReport report;
  report.used = SparseSolverKind::amg_pcg;
  report.levels = cycle.levels();
  report.setup_seconds = seconds_since(start);
  conjugate_gradients_to_tolerance(
      K, [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { cycle.apply(r, z); }, f, u,
      options.tolerance, options.max_iterations, nullptr, report, cycle.blocks());
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

/// K and the V-cycle on its hierarchy (K is the finest level). Destroyed in reverse order.
struct SpdPreconditioner::Amg {
  SparseMatrixRM K;
  AmgVCycle cycle;
  // swap, not move: Eigen 3.4's SparseMatrix has no move constructor, so std::move copies it.
  Amg(SparseMatrixRM& matrix, int block_size) : K(take(matrix)), cycle(K, block_size) {}
  static SparseMatrixRM take(SparseMatrixRM& matrix) {
    SparseMatrixRM out;
    out.swap(matrix);
    return out;  // NRVO: no copy
  }
};

SpdPreconditioner::SpdPreconditioner(SparseMatrixRM&& K, const SparseSolverOptions& options)
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
    amg_ = std::make_unique<Amg>(K, options.block_size);
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
    amg_->cycle.apply(r, z);
  }
}

// ---------------------------------------------------------------------------------------------
// ShiftedSpdSolver

// Here, not in amg_vcycle.cpp: that file is compiled without FMA contraction
// (src/dsm/CMakeLists.txt), and this sum has always been compiled with it, so A Z keeps its bits.
Eigen::MatrixXd shifted_coarse_product(const Eigen::MatrixXd& Z, const Eigen::MatrixXd& KZ,
                                       const Eigen::VectorXd& shift, const AddedProduct* added) {
  if (Z.cols() == 0) return {};
  Eigen::MatrixXd AZ = KZ + shift.asDiagonal() * Z;
  if (added) {
    for (Eigen::Index k = 0; k < Z.cols(); ++k) (*added)(Z.col(k).data(), AZ.col(k).data());
  }
  return AZ;
}

ShiftedSpdSolver::ShiftedSpdSolver(SparseMatrixRM&& K, const SparseSolverOptions& options)
    : kind_(chosen_solver(K, options)), options_(options) {
  K_.swap(K);  // Eigen 3.4's SparseMatrix has no move constructor: std::move alone would copy it
  K_.makeCompressed();
  const auto n = static_cast<std::size_t>(K_.rows());
  diagonal_.assign(n, -1);
  base_.assign(n, 0.0);
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  for (std::size_t i = 0; i < n; ++i) {
    for (int e = outer[i]; e < outer[i + 1]; ++e) {
      if (static_cast<std::size_t>(inner[e]) == i) diagonal_[i] = e;
    }
    if (diagonal_[i] < 0) {
      throw std::invalid_argument("ShiftedSpdSolver: row " + std::to_string(i) +
                                  " has no diagonal entry");
    }
    base_[i] = K_.valuePtr()[diagonal_[i]];
  }
}

ShiftedSpdSolver::~ShiftedSpdSolver() = default;

void ShiftedSpdSolver::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  if (const BlockCsr<double>* blocks =
          amg_ ? amg_->blocks() : nullptr) {  // the same sums, fewer bytes
    y.resize(K_.rows());
    blocks->multiply(x.data(), y.data());
  } else {
    y = K_ * x;
  }
  if (shift_.size() == x.size()) y -= shift_.cwiseProduct(x);
}

void ShiftedSpdSolver::set_coarse_space(Eigen::MatrixXd Z) {
  if (Z.cols() > 0 && Z.rows() != K_.rows())
    throw std::invalid_argument("ShiftedSpdSolver::set_coarse_space: Z has the wrong rows");
  Z_ = std::move(Z);
  // K Z in one pass over K, on all threads (Eigen's product with a dense matrix runs on one),
  // with Z's rows side by side.
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = Z_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> product(Z_.rows(),
                                                                                 Z_.cols());
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  const double* value = K_.valuePtr();
  const auto n = static_cast<Eigen::Index>(K_.rows());
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < n; ++i) {
    product.row(i).setZero();
    for (int k = outer[i]; k < outer[i + 1]; ++k) product.row(i) += value[k] * rows.row(inner[k]);
  }
  KZ_ = product;
  if (shift_.size() == K_.rows()) KZ_ -= shift_.asDiagonal() * Z_;  // K_ holds a shift once set up
}

SparseSolveReport ShiftedSpdSolver::solve(const Eigen::VectorXd& shift, const Eigen::VectorXd& f,
                                          Eigen::VectorXd& u, double tolerance,
                                          const AddedProduct* added) {
  const auto start = Clock::now();
  const Eigen::Index n = K_.rows();
  if (shift.size() != n || f.size() != n)
    throw std::invalid_argument("ShiftedSpdSolver::solve: sizes differ");
  SparseSolveReport report;
  report.used = kind_;
  if (!cholmod_ && !amg_) {  // the first solve: the preconditioner of K + diag(shift)
    double* value = K_.valuePtr();
    for (Eigen::Index i = 0; i < n; ++i)
      value[diagonal_[static_cast<std::size_t>(i)]] = base_[static_cast<std::size_t>(i)] + shift[i];
    shift_ = shift;
    if (kind_ == SparseSolverKind::cholmod) {
      cholmod_ = std::make_unique<CholmodFactor>(K_);
      report.peak_bytes = cholmod_->peak_bytes();
    } else {
      hypre::start();
      amg_ = std::make_unique<AmgVCycle>(K_, options_.block_size, options_.nodal_coarsening);
      report.levels = amg_->levels();
    }
    report.setup_seconds = seconds_since(start);
  }
  const Preconditioner M = [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    if (cholmod_)
      cholmod_->solve(r, z);
    else
      amg_->apply(r, z);
  };
  // The operator: K_ (which holds shift_) plus the rest of the shift and `added`; K_ in blocks
  // when AMG has them.
  const Eigen::VectorXd extra = shift - shift_;
  const BlockCsr<double>* blocks = amg_ ? amg_->blocks() : nullptr;
  const CoarseCorrection coarse(
      Z_, amg_ ? shifted_coarse_product(Z_, KZ_, shift, added) : Eigen::MatrixXd());
  conjugate_gradients_to_tolerance(K_, M, f, u, tolerance, options_.max_iterations, &extra, report,
                                   blocks, added, &coarse);
  report.seconds = seconds_since(start);
  if (!(report.relative_residual <= tolerance)) {
    throw InputError("linear solve (" + std::string(to_string(kind_)) + ")",
                     "conjugate gradients did not reach the tolerance " + format_number(tolerance) +
                         " in " + std::to_string(report.iterations) +
                         " iterations (relative residual " +
                         format_number(report.relative_residual) + ")",
                     "use more iterations; check that the platens touch the sample");
  }
  return report;
}

}  // namespace bpm
