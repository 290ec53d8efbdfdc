#include "solvers/amg_vcycle.hpp"

#include <_hypre_parcsr_ls.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

#include <omp.h>

#include <Eigen/Cholesky>

#include "core/parallel.hpp"
#include "solvers/block_csr.hpp"
#include "solvers/cholmod_factor.hpp"
#include "solvers/hypre_support.hpp"

namespace bpm {
namespace {

struct HypreFree {
  void operator()(void* p) const noexcept { hypre_Free(p, HYPRE_MEMORY_HOST); }
};

/// A compressed-row matrix read by the cycle: a view of K (the finest level), arrays taken over
/// from hypre's hierarchy (freed the way hypre allocated them), or an Eigen matrix (P^T).
struct Csr {
  int rows = 0, cols = 0;
  const int* outer = nullptr;
  const int* inner = nullptr;
  const double* value = nullptr;
  std::unique_ptr<int[], HypreFree> hypre_outer, hypre_inner;
  std::unique_ptr<double[], HypreFree> hypre_value;
  std::unique_ptr<SparseMatrixRM> eigen;  // on the heap: the pointers above stay valid when moved
  const BlockCsr<double>* blocks = nullptr;  // K (the finest level) in blocks, read instead

  static Csr view(const SparseMatrixRM& K) {
    Csr c;
    c.rows = static_cast<int>(K.rows());
    c.cols = static_cast<int>(K.cols());
    c.outer = K.outerIndexPtr();
    c.inner = K.innerIndexPtr();
    c.value = K.valuePtr();
    return c;
  }
  /// Takes the arrays of a one-process hypre matrix (its local block); hypre keeps empty shells.
  static Csr take(hypre_ParCSRMatrix* m) {
    if (hypre_CSRMatrixNumCols(hypre_ParCSRMatrixOffd(m)) != 0) {
      throw std::logic_error("AmgVCycle: a hypre level has off-process columns");
    }
    hypre_CSRMatrix* local = hypre_ParCSRMatrixDiag(m);
    Csr c;
    c.rows = hypre_CSRMatrixNumRows(local);
    c.cols = hypre_CSRMatrixNumCols(local);
    c.hypre_outer.reset(hypre_CSRMatrixI(local));
    c.hypre_inner.reset(hypre_CSRMatrixJ(local));
    c.hypre_value.reset(hypre_CSRMatrixData(local));
    hypre_CSRMatrixI(local) = nullptr;
    hypre_CSRMatrixJ(local) = nullptr;
    hypre_CSRMatrixData(local) = nullptr;
    c.outer = c.hypre_outer.get();
    c.inner = c.hypre_inner.get();
    c.value = c.hypre_value.get();
    return c;
  }
  static Csr own(SparseMatrixRM&& M) {
    Csr c;
    c.eigen = std::make_unique<SparseMatrixRM>(std::move(M));
    c.eigen->makeCompressed();
    c.rows = static_cast<int>(c.eigen->rows());
    c.cols = static_cast<int>(c.eigen->cols());
    c.outer = c.eigen->outerIndexPtr();
    c.inner = c.eigen->innerIndexPtr();
    c.value = c.eigen->valuePtr();
    return c;
  }
  Eigen::Map<const SparseMatrixRM> map() const {
    return {rows, cols, outer[rows], outer, inner, value};
  }

  /// y = A x (add: y += A x). Each row is summed in stored order on one thread.
  void multiply(const double* x, double* y, bool add = false) const {
    if (!single_blocks.empty()) return single_blocks.multiply(x, y, add);
    if (!single.empty()) return product(single.data(), x, y, add);
    if (blocks) return blocks->multiply(x, y, add);
    product(value, x, y, add);
  }

  /// The values rounded to float for the products from now on: the products stream 8 bytes an
  /// entry instead of 12 (they are bound by memory bandwidth), sums stay double. For the V-cycle's
  /// operators only: it is a preconditioner, and symmetric entries stay equal when rounded, so the
  /// cycle stays a fixed symmetric map. CG's own products use K in double.
  void round_to_single() {
    if (blocks) {  // the finest level: in blocks instead
      single_blocks = blocks->converted<float>();
      return;
    }
    single.resize(static_cast<std::size_t>(outer[rows]));
#pragma omp parallel for schedule(static) if (rows > kParallelRows)
    for (int i = 0; i < rows; ++i) {
      for (int k = outer[i]; k < outer[i + 1]; ++k) single[k] = static_cast<float>(value[k]);
    }
  }

 private:
  std::vector<float> single;
  BlockCsr<float> single_blocks;

  template <typename Value>
  void product(const Value* values, const double* x, double* y, bool add) const {
#pragma omp parallel for schedule(static) if (rows > kParallelRows)
    for (int i = 0; i < rows; ++i) {
      double sum = 0.0;
      for (int k = outer[i]; k < outer[i + 1]; ++k)
        sum += static_cast<double>(values[k]) * x[inner[k]];
      y[i] = add ? y[i] + sum : sum;
    }
  }
};

/// a . b, summed in a fixed order (the same rounding for any number of threads).
double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return fixed_order_sum(a.size(), [&](std::size_t i) {
    return a[static_cast<Eigen::Index>(i)] * b[static_cast<Eigen::Index>(i)];
  });
}

/// Chebyshev interval on D^-1 A: [kLowerFraction, 1] x kUpperMargin x (power-iteration estimate of
/// its largest eigenvalue). The smoother damps the upper part of the spectrum; the coarse levels
/// take the rest. 0.2-0.4 gave 26-27 iterations on case 1; 6 power iterations instead of 12 gave 37
/// (the estimate was too low); degree 3 saved 2 iterations for a third more work a cycle.
constexpr double kLowerFraction = 0.3;
constexpr double kUpperMargin = 1.1;
constexpr int kPowerIterations = 12;

}  // namespace

struct AmgVCycle::Level {
  Csr A;     ///< this level's operator
  Csr P, R;  ///< interpolation from the next coarser level, and restriction R = P^T
  Eigen::VectorXd inverse_diagonal;
  double upper = 0.0;             ///< Chebyshev's upper bound on the eigenvalues of D^-1 A
  Eigen::VectorXd b, x, r, d, t;  ///< right-hand side, iterate, and work vectors

  void allocate() {
    inverse_diagonal.resize(A.rows);
#pragma omp parallel for schedule(static) if (A.rows > kParallelRows)
    for (int i = 0; i < A.rows; ++i) {
      double diagonal = 0.0;
      for (int k = A.outer[i]; k < A.outer[i + 1]; ++k) {
        if (A.inner[k] == i) diagonal = A.value[k];
      }
      inverse_diagonal[i] = diagonal > 0.0 ? 1.0 / diagonal : 0.0;
    }
    for (Eigen::VectorXd* v : {&b, &x, &r, &d, &t}) v->setZero(A.rows);
  }

  /// Largest eigenvalue of D^-1 A (similar to the SPD D^-1/2 A D^-1/2, so real and positive), by
  /// power iteration from a fixed pseudo-random vector.
  void estimate_upper_bound() {
    Eigen::VectorXd& v = r;
    Eigen::VectorXd& w = t;
    for (int i = 0; i < A.rows; ++i) {
      const std::uint32_t hash = static_cast<std::uint32_t>(i) * 2654435761u;
      v[i] = static_cast<double>(hash >> 8) / static_cast<double>(1u << 24) - 0.5;
    }
    double estimate = 0.0;
    for (int iteration = 0; iteration < kPowerIterations; ++iteration) {
      const double length = std::sqrt(dot(v, v));
      if (!(length > 0.0)) break;
      v /= length;
      A.multiply(v.data(), w.data());
      w.array() *= inverse_diagonal.array();
      estimate = dot(v, w);
      std::swap(v, w);
    }
    upper = kUpperMargin * estimate;
    r.setZero();
    t.setZero();
  }

  /// Chebyshev iteration of degree 2 on D^-1 A x = D^-1 b over [kLowerFraction, 1] upper (Saad,
  /// Iterative Methods, Alg. 12.1), from x = 0 or from the current x.
  void smooth(bool from_zero) {
    const double lower = kLowerFraction * upper;
    const double theta = 0.5 * (upper + lower), delta = 0.5 * (upper - lower);
    const double sigma = theta / delta;
    const int n = A.rows;
    if (!from_zero) A.multiply(x.data(), t.data());
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (int i = 0; i < n; ++i) {
      const double residual = from_zero ? b[i] : b[i] - t[i];
      d[i] = inverse_diagonal[i] * residual / theta;
      x[i] = from_zero ? d[i] : x[i] + d[i];
    }
    A.multiply(x.data(), t.data());
    const double rho = 1.0 / sigma;
    const double rho_next = 1.0 / (2.0 * sigma - rho);
    const double keep = rho_next * rho, step = 2.0 * rho_next / delta;
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (int i = 0; i < n; ++i) {
      d[i] = keep * d[i] + step * inverse_diagonal[i] * (b[i] - t[i]);
      x[i] += d[i];
    }
  }
};

AmgVCycle::AmgVCycle(SparseMatrixRM& K, int block_size, bool nodal) {
  if (K.rows() != K.cols() || K.rows() == 0)
    throw std::invalid_argument("AmgVCycle: K must be square and not empty");
  K.makeCompressed();
  auto finest = std::make_unique<Level>();
  finest->A = Csr::view(K);
  std::vector<Csr> operators, interpolations;
  {
    Eigen::VectorXd zero_b = Eigen::VectorXd::Zero(K.rows()), zero_x = zero_b;
    const hypre::BorrowedMatrix A(K);
    const hypre::BorrowedVector b(zero_b), x(zero_x);
    // hypre builds the hierarchy on one core, on this thread (its MPI calls stay here: one thread
    // at a time may call MPI). Meanwhile a second thread prepares the finest level, which
    // needs only K: its diagonal, K in blocks, in double for CG's products and rounded to float
    // for the cycle's, and the Chebyshev bound (together ~1 s on one core at 6e5 unknowns, which
    // followed hypre's set-up until 2026-12-03). K's rows are in hypre's order until A is
    // destroyed; none of these depends on the order.
    std::exception_ptr failure;
    std::jthread prepare([&] {
      try {
        omp_set_num_threads(1);
        finest->allocate();
        auto blocks =
            BlockCsr<double>::find(static_cast<int>(K.rows()), static_cast<int>(K.cols()),
                                   K.outerIndexPtr(), K.innerIndexPtr(), K.valuePtr(), block_size);
        if (!blocks.empty()) {
          finest_blocks_ = std::make_unique<BlockCsr<double>>(std::move(blocks));
          finest->A.blocks = finest_blocks_.get();
          finest->A.round_to_single();  // CSR would be rounded in hypre's order: after it, below
        }
        // After the blocks: the power iteration's products read the float blocks (on the cylinder
        // 12 products of ~0.02 s instead of ~0.1 s in CSR and double on this one thread).
        finest->estimate_upper_bound();
      } catch (...) {
        failure = std::current_exception();
      }
    });
    hypre::BoomerAmg amg;  // destroyed before A, to which it refers
    hypre::check(HYPRE_BoomerAMGCreate(&amg.h), "HYPRE_BoomerAMGCreate");
    hypre::configure_boomeramg(amg.h, static_cast<HYPRE_Int>(K.rows()), block_size, nodal);
    hypre::check(HYPRE_BoomerAMGSetup(amg.h, A.get(), b.get(), x.get()), "HYPRE_BoomerAMGSetup");
    auto* data = reinterpret_cast<hypre_ParAMGData*>(amg.h);
    const int count = hypre_ParAMGDataNumLevels(data);
    for (int l = 1; l < count; ++l) operators.push_back(Csr::take(hypre_ParAMGDataAArray(data)[l]));
    for (int l = 0; l + 1 < count; ++l)
      interpolations.push_back(Csr::take(hypre_ParAMGDataPArray(data)[l]));
    prepare.join();
    if (failure) std::rethrow_exception(failure);
  }

  const std::size_t count = operators.size() + 1;
  for (std::size_t l = 0; l < count; ++l) {
    std::unique_ptr<Level> level = l == 0 ? std::move(finest) : std::make_unique<Level>();
    if (l > 0) level->A = std::move(operators[l - 1]);
    if (l + 1 < count) {
      level->P = std::move(interpolations[l]);
      level->R = Csr::own(SparseMatrixRM(level->P.map().transpose()));
      if (l > 0 || !finest_blocks_) level->A.round_to_single();  // blocks: rounded above
    }
    if (l > 0) {
      level->allocate();
      if (l + 1 < count) level->estimate_upper_bound();
    }
    levels_.push_back(std::move(level));
  }
  // The coarsest level is solved exactly. CHOLMOD reads sorted rows; hypre keeps the diagonal
  // first: a column-major copy sorts them (and equals the row-major matrix, A being symmetric).
  const Eigen::SparseMatrix<double, Eigen::ColMajor, int> sorted = levels_.back()->A.map();
  coarsest_ = std::make_unique<CholmodFactor>(SparseMatrixRM(sorted));
}

AmgVCycle::~AmgVCycle() = default;

const BlockCsr<double>* AmgVCycle::blocks() const {
  return finest_blocks_.get();
}

int AmgVCycle::levels() const {
  return static_cast<int>(levels_.size());
}

void AmgVCycle::cycle(std::size_t l) {
  Level& level = *levels_[l];
  if (l + 1 == levels_.size()) {
    coarsest_->solve(level.b, level.x);
    return;
  }
  level.smooth(/*from_zero=*/true);
  level.A.multiply(level.x.data(), level.t.data());
  const int n = level.A.rows;
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (int i = 0; i < n; ++i) level.r[i] = level.b[i] - level.t[i];
  Level& coarse = *levels_[l + 1];
  level.R.multiply(level.r.data(), coarse.b.data());
  cycle(l + 1);
  level.P.multiply(coarse.x.data(), level.x.data(), /*add=*/true);
  level.smooth(/*from_zero=*/false);
}

void AmgVCycle::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  Level& finest = *levels_.front();
  if (r.size() != finest.A.rows)
    throw std::invalid_argument("AmgVCycle::apply: r has the wrong size");
  finest.b = r;
  cycle(0);
  z = finest.x;
}

namespace {

/// Z^T r for a tall Z, summed over fixed blocks of rows in a fixed order (the same rounding for
/// any number of threads).
Eigen::VectorXd transposed_product(const Eigen::MatrixXd& Z, const Eigen::VectorXd& r) {
  constexpr Eigen::Index kBlock = 4096;
  const Eigen::Index n = Z.rows(), blocks = (n + kBlock - 1) / kBlock;
  Eigen::MatrixXd partial(Z.cols(), blocks);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (Eigen::Index b = 0; b < blocks; ++b) {
    const Eigen::Index begin = b * kBlock, rows = std::min(kBlock, n - begin);
    partial.col(b).noalias() = Z.middleRows(begin, rows).transpose() * r.segment(begin, rows);
  }
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(Z.cols());
  for (Eigen::Index b = 0; b < blocks; ++b) sum += partial.col(b);
  return sum;
}

/// y -= Z c, row by row.
void subtract_product(const Eigen::MatrixXd& Z, const Eigen::VectorXd& c, Eigen::VectorXd& y) {
  const Eigen::Index n = Z.rows(), m = Z.cols();
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (Eigen::Index i = 0; i < n; ++i) {
    double s = 0.0;
    for (Eigen::Index k = 0; k < m; ++k) s += Z(i, k) * c[k];
    y[i] -= s;
  }
}

}  // namespace

CoarseCorrection::CoarseCorrection(const Eigen::MatrixXd& Z, Eigen::MatrixXd AZ)
    : Z_(Z), AZ_(std::move(AZ)) {
  if (Z.cols() == 0 || AZ_.rows() != Z.rows() || AZ_.cols() != Z.cols()) return;
  Eigen::MatrixXd E(Z.cols(), Z.cols());
  for (Eigen::Index k = 0; k < Z.cols(); ++k) E.col(k) = transposed_product(Z, AZ_.col(k));
  E = 0.5 * (E + E.transpose());  // A is symmetric: only round-off differs
  const Eigen::LLT<Eigen::MatrixXd> factor(E);
  if (factor.info() != Eigen::Success) return;
  inverse_ = factor.solve(Eigen::MatrixXd::Identity(E.rows(), E.cols()));
  if (!inverse_.allFinite()) inverse_.resize(0, 0);
}

void CoarseCorrection::start(Eigen::VectorXd& u, Eigen::VectorXd& r) const {
  const Eigen::VectorXd c = inverse_ * transposed_product(Z_, r);
  subtract_product(Z_, -c, u);
  subtract_product(AZ_, c, r);
}

void CoarseCorrection::project(Eigen::VectorXd& z) const {
  subtract_product(Z_, inverse_ * transposed_product(AZ_, z), z);
}

void conjugate_gradients_to_tolerance(const std::function<int(int)>& cg,
                                      const std::function<double()>& true_residual,
                                      double tolerance, int max_iterations,
                                      SparseSolveReport& report) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    report.iterations += cg(max_iterations - report.iterations);
    report.relative_residual = true_residual();
    if (report.relative_residual <= tolerance || !std::isfinite(report.relative_residual) ||
        report.iterations >= max_iterations) {
      return;
    }
  }
}

int preconditioned_conjugate_gradients(const SparseMatrixRM& K, const Preconditioner& M,
                                       const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                       double tolerance, int max_iterations,
                                       const Eigen::VectorXd* shift, const BlockCsr<double>* blocks,
                                       const AddedProduct* added, const CoarseCorrection* coarse) {
  Csr A = Csr::view(K);
  A.blocks = blocks;
  const LinearOperator product = [&](const Eigen::VectorXd& x,
                                     Eigen::VectorXd& y) {  // (K + diag(shift) + added) x
    y.resize(x.size());
    A.multiply(x.data(), y.data());
    if (shift) y.array() += shift->array() * x.array();
    if (added) (*added)(x.data(), y.data());
  };
  return preconditioned_conjugate_gradients(product, M, f, u, tolerance, max_iterations, coarse);
}

int preconditioned_conjugate_gradients(const LinearOperator& multiply, const Preconditioner& M,
                                       const Eigen::VectorXd& f, Eigen::VectorXd& u,
                                       double tolerance, int max_iterations,
                                       const CoarseCorrection* coarse) {
  if (coarse && coarse->empty()) coarse = nullptr;
  const Eigen::Index n = f.size();
  if (u.size() != n) u = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd r(n), z(n), p(n), q(n);
  if (u.isZero(0.0)) {
    q.setZero();  // A 0 = 0: a Newton step starts from zero, and a product costs ~0.03 s at 6e5
                  // rows
  } else {
    multiply(u, q);
  }
  r = f - q;
  if (coarse) coarse->start(u, r);
  const double f_norm = std::sqrt(dot(f, f));
  const double target = tolerance * (f_norm > 0.0 ? f_norm : 1.0);
  if (std::sqrt(dot(r, r)) <= target) return 0;
  M(r, z);
  if (coarse) coarse->project(z);
  p = z;
  double rz = dot(r, z);
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    multiply(p, q);
    const double curvature = dot(p, q);
    if (!(curvature > 0.0) || !(rz > 0.0)) return iteration;  // not SPD: the true residual tells
    const double alpha = rz / curvature;
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (Eigen::Index i = 0; i < n; ++i) {
      u[i] += alpha * p[i];
      r[i] -= alpha * q[i];
    }
    if (std::sqrt(dot(r, r)) <= target) return iteration;
    M(r, z);
    if (coarse) coarse->project(z);
    const double rz_next = dot(r, z);
    const double beta = rz_next / rz;
    rz = rz_next;
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (Eigen::Index i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
  }
  return max_iterations;
}

}  // namespace bpm
