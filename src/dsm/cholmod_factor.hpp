#pragma once
/// A Cholesky factorisation of a symmetric positive definite K (SuiteSparse CHOLMOD, supernodal),
/// kept for many solves: the nonlinear DSM's preconditioner factorises once per Newton setup and
/// solves once per Krylov iteration.
#include <Eigen/Core>
#include <memory>

#include "dsm/sparse_solver.hpp"

namespace bpm {

class CholmodFactor {
 public:
  /// K as for solve_spd (full storage, row-major). Throws InputError if K is not positive definite.
  explicit CholmodFactor(const SparseMatrixRM& K);
  ~CholmodFactor();
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  /// z = K^-1 r.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace bpm
