#pragma once
/// The Cholesky factorisation of a symmetric positive definite K (SuiteSparse CHOLMOD,
/// supernodal), kept for any number of solves: solve_spd factorises once and solves once; the
/// nonlinear DSM's preconditioner factorises once per Newton setup and solves once per Krylov
/// iteration.
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <string_view>

#include "solvers/sparse_solver.hpp"

namespace bpm {

class CholmodFactor {
 public:
  /// K as for solve_spd (full storage, row-major; only one triangle is read, without a copy).
  /// Throws InputError if K is singular to working precision (a free rigid-body mode) or CHOLMOD
  /// fails (out of memory: use the AMG solver).
  explicit CholmodFactor(const SparseMatrixRM& K);
  ~CholmodFactor();
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  /// z = K^-1 r.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  /// CHOLMOD's own count of its peak memory, bytes.
  std::size_t peak_bytes() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// The error for a stiffness matrix with a free rigid-body mode, naming the solver.
[[noreturn]] void throw_rigid_body_mode(std::string_view solver);

}  // namespace bpm
