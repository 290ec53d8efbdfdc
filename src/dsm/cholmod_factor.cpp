#include "dsm/cholmod_factor.hpp"

#include <cholmod.h>

#include <string>

#include "core/error.hpp"

namespace bpm {

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
  cholmod_common* c = &state_->common;
  c->print = 0;
  c->supernodal = CHOLMOD_SUPERNODAL;
  const auto n = static_cast<std::size_t>(K.rows());
  // K is symmetric: its row-major arrays are also a column-major K; stype = 1 reads one triangle.
  cholmod_sparse A{};
  A.nrow = n;
  A.ncol = n;
  A.nzmax = static_cast<std::size_t>(K.nonZeros());
  A.p = const_cast<int*>(K.outerIndexPtr());  // CHOLMOD only reads A
  A.i = const_cast<int*>(K.innerIndexPtr());
  A.x = const_cast<double*>(K.valuePtr());
  A.stype = 1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 0;
  A.packed = 1;
  state_->factor = cholmod_analyze(&A, c);
  if (state_->factor) cholmod_factorize(&A, state_->factor, c);
  if (!state_->factor || c->status != CHOLMOD_OK || state_->factor->minor < n) {
    throw InputError("linear solve (cholmod)", "K is not positive definite (status " + std::to_string(c->status) + ")",
                     "a rigid-body mode is free: check that the sample is bonded from platen to platen");
  }
}

CholmodFactor::~CholmodFactor() = default;

void CholmodFactor::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  cholmod_common* c = &state_->common;
  const auto n = static_cast<std::size_t>(r.size());
  cholmod_dense b{};
  b.nrow = n;
  b.ncol = 1;
  b.nzmax = n;
  b.d = n;
  b.x = const_cast<double*>(r.data());
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, state_->factor, &b, c);
  if (!x) throw InputError("linear solve (cholmod)", "the triangular solves failed", "");
  z = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), r.size());
  cholmod_free_dense(&x, c);
}

}  // namespace bpm
