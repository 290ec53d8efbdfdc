#include "solvers/cholmod_factor.hpp"

#include <cholmod.h>
#include <omp.h>

#include <limits>
#include <string>

#include "core/error.hpp"

namespace bpm {

void throw_rigid_body_mode(std::string_view solver) {
  throw InputError("linear solve (" + std::string(solver) + ")",
                   "the stiffness matrix is singular: a rigid-body mode is unconstrained",
                   "fix more degrees of freedom, and check that the sample is one connected body "
                   "(a particle or cluster without bonds can move freely)");
}

namespace {

/// CHOLMOD 5 wraps small scatter loops of its factorisation in OpenMP regions of up to 4 threads.
/// On 2 cores shared with other processes their spin-waits made a 5,400-unknown factorisation
/// 7-20x slower (0.7-2.3 s against 0.08-0.1 s on one thread), so CHOLMOD runs on one OpenMP
/// thread; its dense kernels are BLAS calls, which keep their own threads.
class OneOpenMPThread {
 public:
  OneOpenMPThread() : previous_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~OneOpenMPThread() { omp_set_num_threads(previous_); }
  OneOpenMPThread(const OneOpenMPThread&) = delete;
  OneOpenMPThread& operator=(const OneOpenMPThread&) = delete;

 private:
  int previous_;
};

/// min over pivots of d_j / K_pp (d_j = L_jj^2, p = Perm[j]): the pivots of the diagonally scaled
/// matrix, so independent of the units of the unknowns (m against rad differ by r^2 in K). A free
/// rigid-body mode leaves round-off in one of them (their product is det = 0); sound structures
/// give 0.1-0.4 (lattices), 0.03 (a column of 400 particles).
double smallest_relative_pivot(const cholmod_factor& L, const Eigen::VectorXd& diagonal) {
  const auto* perm = static_cast<const int*>(L.Perm);
  const auto* x = static_cast<const double*>(L.x);
  double smallest = std::numeric_limits<double>::infinity();
  auto visit = [&](int j, double pivot) {
    const double a = diagonal[perm != nullptr ? perm[j] : j];
    smallest = std::min(smallest, a > 0.0 ? pivot / a : 0.0);
  };
  if (L.is_super) {
    const auto* super = static_cast<const int*>(L.super);
    const auto* pi = static_cast<const int*>(L.pi);
    const auto* px = static_cast<const int*>(L.px);
    for (std::size_t s = 0; s < L.nsuper; ++s) {
      const int rows = pi[s + 1] - pi[s];  // each supernode is a dense column-major block
      for (int j = super[s]; j < super[s + 1]; ++j) {
        const double l = x[px[s] + (j - super[s]) * (rows + 1)];
        visit(j, l * l);
      }
    }
  } else {
    const auto* p = static_cast<const int*>(L.p);
    for (int j = 0; j < static_cast<int>(L.n); ++j) {
      const double d = x[p[j]];  // the diagonal comes first in each column
      visit(j, L.is_ll ? d * d : d);
    }
  }
  return smallest;
}

}  // namespace

struct CholmodFactor::State {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  State() { cholmod_start(&common); }
  ~State() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

CholmodFactor::CholmodFactor(const SparseMatrixRM& K) : state_(std::make_unique<State>()) {
  const OneOpenMPThread serial;
  cholmod_common* c = &state_->common;
  c->print = 0;  // failures become exceptions with a fix; CHOLMOD's own messages would repeat them
  c->supernodal = CHOLMOD_SUPERNODAL;
  const auto n = static_cast<std::size_t>(K.rows());
  // No copy: K is symmetric, so its row-major arrays are also a valid column-major K. stype = 1
  // reads the upper triangle, the form CHOLMOD's numeric factorisation uses without a transpose.
  cholmod_sparse A{};
  A.nrow = n;
  A.ncol = n;
  A.nzmax = static_cast<std::size_t>(K.nonZeros());
  A.p = const_cast<int*>(K.outerIndexPtr());  // CHOLMOD takes non-const pointers but only reads A
  A.i = const_cast<int*>(K.innerIndexPtr());
  A.x = const_cast<double*>(K.valuePtr());
  A.stype = 1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 0;  // Eigen does not promise sorted inner indices; CHOLMOD does not need them
  A.packed = 1;

  cholmod_factor*& L = state_->factor;
  L = cholmod_analyze(&A, c);
  if (L != nullptr) cholmod_factorize(&A, L, c);
  if (L != nullptr && (c->status == CHOLMOD_NOT_POSDEF || L->minor < L->n))
    throw_rigid_body_mode("cholmod");
  if (L == nullptr || c->status < CHOLMOD_OK) {
    throw InputError(
        "linear solve (cholmod)",
        c->status == CHOLMOD_OUT_OF_MEMORY
            ? "out of memory factorising K (" + std::to_string(n) + " unknowns)"
            : "the factorisation failed (CHOLMOD status " + std::to_string(c->status) + ")",
        "use --solver amg");
  }
  // Round-off can leave a small positive pivot where a free rigid-body mode has a zero one.
  const double threshold = 1e3 * std::numeric_limits<double>::epsilon();
  if (smallest_relative_pivot(*L, K.diagonal()) < threshold) throw_rigid_body_mode("cholmod");
}

CholmodFactor::~CholmodFactor() = default;

std::size_t CholmodFactor::peak_bytes() const {
  return state_->common.memory_usage;
}

void CholmodFactor::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const OneOpenMPThread serial;
  cholmod_common* c = &state_->common;
  const auto n = static_cast<std::size_t>(r.size());
  cholmod_dense b{};
  b.nrow = n;
  b.ncol = 1;
  b.nzmax = n;
  b.d = n;
  b.x = const_cast<double*>(r.data());  // only read
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, state_->factor, &b, c);
  if (x == nullptr) {
    throw InputError(
        "linear solve (cholmod)",
        "the triangular solves failed (CHOLMOD status " + std::to_string(c->status) + ")",
        "use --solver amg");
  }
  z = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), r.size());
  cholmod_free_dense(&x, c);
}

}  // namespace bpm
