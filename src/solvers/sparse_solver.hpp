#pragma once
/// Solvers for the symmetric positive definite systems K u = f of the direct stiffness method
/// (Jarolin section 3.1, Eq. 9): a sparse direct Cholesky factorisation (SuiteSparse CHOLMOD) for
/// small and medium systems, and conjugate gradients preconditioned with algebraic multigrid for
/// large ones (the hierarchy from hypre BoomerAMG, the cycle on all threads: amg_vcycle.hpp).
/// `automatic` picks by size; the user can override it.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstddef>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

namespace bpm {

enum class SparseSolverKind { automatic, cholmod, amg_pcg };

/// "auto", "cholmod", "amg" <-> kind; parse throws InputError naming `where` and the valid names.
std::string_view to_string(SparseSolverKind kind);
SparseSolverKind parse_sparse_solver(std::string_view name, std::string_view where);

struct SparseSolverOptions {
  SparseSolverKind kind = SparseSolverKind::automatic;
  /// Iterative solvers stop at ||f - K u|| <= tolerance ||f|| (Jarolin: 1e-6).
  double tolerance = 1e-6;
  int max_iterations = 2000;
  /// `automatic` uses CHOLMOD up to this many unknowns and AMG-PCG above. Measured with
  /// bench/sparse_solvers.cpp (clamped TBBM lattices, 6 DOF, tolerance 1e-6), s:
  ///   unknowns      1,080  2,688  5,400  9,504  18,900  45,600  156,600  374,400
  ///   CHOLMOD       0.005  0.015  0.042  0.12   0.38    2.4     17       102
  ///   AMG-PCG       0.005  0.017  0.038  0.089  0.18    0.50    1.7      5.2
  ///   CHOLMOD, MB   1.7    5.6    16     34     91      320     1650     6290
  ///   AMG-PCG, MB   0.5    1.6    3.7    7.0    15      39      149      369
  /// (CHOLMOD on one thread; AMG-PCG with the threaded V-cycle on 2; measured before the V-cycle
  /// and CG read K in 6x6 blocks, which adds about 0.72 times K's CSR arrays), plus 0.4 s once per
  /// process for AMG (MPI's start and stop). A generated random packing (bpmkit generate, 17,994
  /// and 86,802 unknowns): CHOLMOD 0.50 s and 4.1 s (540 MB), AMG 0.22 s and 1.6 s (hypre's own
  /// V-cycle). For one solve per process the two meet near 20,000-25,000 unknowns; below, the
  /// direct solver costs under 0.5 s and 100 MB and needs no tolerance.
  std::size_t direct_limit = 20000;
  /// Unknowns per node (6: translation + rotation, 3: translation only); lets AMG treat the
  /// unknowns of one particle as a block (hypre's systems AMG, num_functions).
  int block_size = 6;
  /// AMG-PCG: hypre coarsens by particle instead of by unknown (amg_vcycle.cpp). The DSM with
  /// walls, whose solves deflate the rigid-body modes (ShiftedSpdSolver::set_coarse_space), sets
  /// it: on the 1e5-particle cylinder its first coarse level has 2.7 M entries instead of 8.3 M,
  /// for the same CG iterations (2026-12-03).
  bool nodal_coarsening = false;
};

struct SparseSolveReport {
  SparseSolverKind used = SparseSolverKind::cholmod;
  int iterations = 0;              ///< 0 for the direct solver
  double relative_residual = 0.0;  ///< ||f - K u|| / ||f||, computed after the solve
  double seconds = 0.0;            ///< setup + solve, wall clock (without MPI's one-time start)
  std::size_t peak_bytes = 0;      ///< CHOLMOD's peak memory (its own count); 0 for AMG-PCG
  int levels = 0;                  ///< AMG-PCG: multigrid levels
  double setup_seconds = 0.0;      ///< AMG-PCG: the hierarchy's set-up (part of `seconds`)
};

/// Solves K u = f. K is symmetric positive definite, stored in full (both triangles), row-major
/// (Eigen's RowMajor SparseMatrix with int indices); it is compressed in place if it is not, and
/// AMG-PCG reads it in place, without a copy: hypre's format puts each row's diagonal entry first,
/// so K's rows are reordered during the solve and restored before it returns (or throws). u holds
/// the initial guess on entry for the iterative solver (zero if its size does not match). Throws
/// InputError if K is singular or not positive definite (a rigid-body mode left free), if the
/// iteration does not reach the tolerance (its true residual, recomputed) or if CHOLMOD runs out of
/// memory. AMG-PCG sees a singular K only through loads that drive a free mode; with balanced loads
/// it returns one of the solutions. The first AMG-PCG solve of a process starts MPI (hypre needs
/// it; no mpirun needed) unless the program already has.
using SparseMatrixRM = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
/// y += A x for a symmetric operator A added to K (contact_change.hpp).
using AddedProduct = std::function<void(const double* x, double* y)>;
SparseSolveReport solve_spd(SparseMatrixRM& K, const Eigen::VectorXd& f, Eigen::VectorXd& u,
                            const SparseSolverOptions& options = {});

class CholmodFactor;

/// An approximate inverse of an SPD K for preconditioning (the nonlinear DSM's Krylov solver):
/// CHOLMOD's exact factor up to options.direct_limit unknowns, one AMG V-cycle above
/// (`cholmod` / `amg_pcg` force one; tolerance and max_iterations are not used). Built once,
/// applied any number of times. K as for solve_spd, taken by value (move it in to save the copy):
/// CHOLMOD keeps only its factor, AMG keeps K, lent to hypre, and the multigrid hierarchy. The AMG
/// variant is a fixed linear operator (zero initial guess, the same V-cycle every time), symmetric
/// like solve_spd's (the same Chebyshev smoother before and after the coarse correction), so CG can
/// use it as well as GMRES.
/// Throws as solve_spd does for a singular K with CHOLMOD; AMG does not detect it.
class SpdPreconditioner {
 public:
  SpdPreconditioner(SparseMatrixRM&& K, const SparseSolverOptions& options);
  ~SpdPreconditioner();
  SpdPreconditioner(const SpdPreconditioner&) = delete;
  SpdPreconditioner& operator=(const SpdPreconditioner&) = delete;

  /// z ~ K^-1 r (exact with CHOLMOD). r has K.rows() entries; z is resized.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  /// cholmod or amg_pcg: the one in use (never automatic).
  SparseSolverKind kind() const;

 private:
  struct Amg;
  SparseSolverKind kind_;
  Eigen::Index size_ = 0;
  std::unique_ptr<CholmodFactor> cholmod_;
  std::unique_ptr<Amg> amg_;
};

class AmgVCycle;

/// The solves of the DSM with walls (dsm_walls.cpp): (K + diag(shift) + added) u = f with K fixed
/// and the shift changing between solves. ShiftedSpdSolver on one process, DistributedShiftedSolver
/// (distributed_solver.hpp) across MPI ranks; vectors are whole (every DOF) in both.
class ShiftedSystem {
 public:
  virtual ~ShiftedSystem() = default;
  /// u (initial guess on entry) solves (K + diag(shift) + added) u = f to
  /// ||f - (K + diag(shift) + added) u|| <= tolerance ||f||.
  virtual SparseSolveReport solve(const Eigen::VectorXd& shift, const Eigen::VectorXd& f,
                                  Eigen::VectorXd& u, double tolerance,
                                  const AddedProduct* added = nullptr) = 0;
  /// y = K x (without any shift).
  virtual void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const = 0;
  /// Vectors the preconditioner represents badly, solved for exactly in each solve (deflation).
  virtual void set_coarse_space(Eigen::MatrixXd Z) = 0;
  virtual SparseSolverKind kind() const = 0;
};

/// Repeated solves of (K + diag(shift)) u = f with K fixed and the shift changing between solves:
/// the platen springs of the DSM on the diagonal while Newton's iteration finds their operating
/// point (dsm_linear.hpp). The preconditioner (CHOLMOD's factor or AMG's hierarchy, chosen by
/// size as in solve_spd) is built once, for the first shift; every solve is conjugate gradients on
/// the shifted operator with it (a diagonal change on the boundary layer costs a few iterations,
/// not a new factorisation or set-up).
class ShiftedSpdSolver final : public ShiftedSystem {
 public:
  /// K as for solve_spd, with an entry on the diagonal of every row. Takes K's storage over (a
  /// swap: Eigen 3.4's SparseMatrix has no move constructor); the argument is left empty.
  ShiftedSpdSolver(SparseMatrixRM&& K, const SparseSolverOptions& options);
  ~ShiftedSpdSolver() override;
  ShiftedSpdSolver(const ShiftedSpdSolver&) = delete;
  ShiftedSpdSolver& operator=(const ShiftedSpdSolver&) = delete;

  /// u (initial guess on entry) solves (K + diag(shift)) u = f to
  /// ||f - (K + diag(shift)) u|| <= tolerance ||f||. With `added`, a symmetric operator near zero
  /// (contacts linearised elsewhere: contact_change.hpp), the system is
  /// (K + added + diag(shift)) u = f, with the same preconditioner. Throws as solve_spd.
  SparseSolveReport solve(const Eigen::VectorXd& shift, const Eigen::VectorXd& f,
                          Eigen::VectorXd& u, double tolerance,
                          const AddedProduct* added = nullptr) override;
  SparseSolverKind kind() const override { return kind_; }
  /// y = K x (without any shift).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  /// Vectors (n x m, m small: the sample's rigid-body modes) that AMG's V-cycle represents
  /// badly, solved for exactly in each solve from now on (CoarseCorrection in amg_vcycle.hpp:
  /// deflation). Zero rows where K's DOFs are held. Used with AMG only (CHOLMOD's factor is exact).
  void set_coarse_space(Eigen::MatrixXd Z) override;

 private:
  SparseSolverKind kind_;
  SparseSolverOptions options_;
  SparseMatrixRM K_;           ///< AMG: K + diag(shift of the set-up) once set up
  std::vector<int> diagonal_;  ///< index of each row's diagonal entry in K_'s values
  std::vector<double> base_;   ///< K's diagonal
  Eigen::VectorXd shift_;      ///< the shift K_ holds (AMG: the one its hierarchy was built for)
  std::unique_ptr<CholmodFactor> cholmod_;
  std::unique_ptr<AmgVCycle> amg_;
  Eigen::MatrixXd Z_;   ///< the coarse space (set_coarse_space)
  Eigen::MatrixXd KZ_;  ///< K Z_ (without any shift)
};

}  // namespace bpm
