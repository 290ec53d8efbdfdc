#pragma once
/// hypre for the DSM's AMG (amg_vcycle.cpp builds its hierarchy with BoomerAMG): start-up,
/// errors, and Eigen's arrays lent to hypre without copies. At the case 3 scale (8e5 particles,
/// 6 DOF) K alone holds 5-6e8 entries (6-7 GB): a copy in hypre's IJ format would double that.
// hypre's MPI: the C API only (OpenMPI's deprecated C++ bindings would need libmpi_cxx).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <Eigen/Core>

#include "solvers/sparse_solver.hpp"

struct hypre_ParCSRMatrix_struct;
struct hypre_ParVector_struct;

namespace bpm::hypre {

/// Starts MPI (as a singleton unless the program started it) and hypre, once per process; both
/// stop at exit. The borrowed objects below call it.
void start();

/// BoomerAMG's coarsening and interpolation for the DSM's K of n unknowns (block_size per
/// particle; nodal: coarsen by particle), the same for the one-process hierarchy (amg_vcycle.cpp)
/// and the distributed solver (distributed_solver.cpp).
void configure_boomeramg(HYPRE_Solver amg, HYPRE_Int n, int block_size, bool nodal);

/// Throws std::runtime_error naming `call` and hypre's description if error != 0.
void check(HYPRE_Int error, const char* call);

/// K's compressed rows lent to hypre as a ParCSR matrix on one process (MPI_COMM_SELF), without a
/// copy. hypre's smoothers and coarsening read each row's diagonal entry first: the constructor
/// rotates it to the front of its row (the other entries keep their order) and the destructor
/// rotates it back, so K is Eigen's sorted matrix again afterwards. Throws std::invalid_argument if
/// K is not square and compressed or a diagonal entry is not stored. K must outlive this object and
/// not be changed through Eigen while it lives.
class BorrowedMatrix {
 public:
  explicit BorrowedMatrix(SparseMatrixRM& K);
  ~BorrowedMatrix();
  BorrowedMatrix(const BorrowedMatrix&) = delete;
  BorrowedMatrix& operator=(const BorrowedMatrix&) = delete;
  HYPRE_ParCSRMatrix get() const;

 private:
  SparseMatrixRM& K_;
  hypre_ParCSRMatrix_struct* matrix_ = nullptr;
};

/// An Eigen vector lent to hypre as a ParVector (one process), without a copy: hypre's solvers read
/// and write v's entries. v must outlive this object and not be resized while it lives.
class BorrowedVector {
 public:
  explicit BorrowedVector(Eigen::VectorXd& v);
  ~BorrowedVector();
  BorrowedVector(const BorrowedVector&) = delete;
  BorrowedVector& operator=(const BorrowedVector&) = delete;
  HYPRE_ParVector get() const;

 private:
  hypre_ParVector_struct* vector_ = nullptr;
};

/// Owner of a BoomerAMG solver object.
struct BoomerAmg {
  HYPRE_Solver h = nullptr;
  BoomerAmg() = default;
  ~BoomerAmg() {
    if (h != nullptr) HYPRE_BoomerAMGDestroy(h);
  }
  BoomerAmg(const BoomerAmg&) = delete;
  BoomerAmg& operator=(const BoomerAmg&) = delete;
};

}  // namespace bpm::hypre
