#include "solvers/distributed_amg.hpp"

#include <HYPRE_IJ_mv.h>
#include <_hypre_parcsr_ls.h>

#include <Eigen/Core>
#include <cstddef>

#include "solvers/hypre_support.hpp"

namespace bpm {
namespace {

double* local_data(HYPRE_ParVector v) {
  return hypre_VectorData(hypre_ParVectorLocalVector(reinterpret_cast<hypre_ParVector*>(v)));
}

}  // namespace

/// The IJ matrix and vectors (the right-hand side and solution of a V-cycle, or the operand and
/// result of a product) and the BoomerAMG hierarchy.
struct DistributedAmg::Hypre {
  HYPRE_IJMatrix matrix = nullptr;
  HYPRE_IJVector in = nullptr, out = nullptr;
  HYPRE_ParCSRMatrix A = nullptr;
  HYPRE_ParVector b = nullptr, x = nullptr;
  hypre::BoomerAmg amg;
  int levels = 0;
  ~Hypre() {
    if (matrix) HYPRE_IJMatrixDestroy(matrix);
    if (in) HYPRE_IJVectorDestroy(in);
    if (out) HYPRE_IJVectorDestroy(out);
  }
};

DistributedAmg::DistributedAmg(SparseMatrixRM& K, const std::vector<int>& row_start,
                               const SparseSolverOptions& options)
    : hypre_(std::make_unique<Hypre>()), rows_(static_cast<int>(K.rows())) {
  hypre::start();
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const int first = row_start[static_cast<std::size_t>(rank)], last = first + rows_ - 1;
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  Hypre& h = *hypre_;
  hypre::check(HYPRE_IJMatrixCreate(MPI_COMM_WORLD, first, last, first, last, &h.matrix),
               "HYPRE_IJMatrixCreate");
  hypre::check(HYPRE_IJMatrixSetObjectType(h.matrix, HYPRE_PARCSR), "HYPRE_IJMatrixSetObjectType");
  // Each row's entries in this rank's columns and in others' (the halo), so hypre allocates once.
  const auto rows = static_cast<std::size_t>(rows_);
  std::vector<HYPRE_Int> own(rows), other(rows), length(rows);
  std::vector<HYPRE_BigInt> row_ids(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    for (int e = outer[i]; e < outer[i + 1]; ++e)
      ++(inner[e] >= first && inner[e] <= last ? own[i] : other[i]);
    length[i] = outer[i + 1] - outer[i];
    row_ids[i] = first + static_cast<int>(i);
  }
  hypre::check(HYPRE_IJMatrixSetDiagOffdSizes(h.matrix, own.data(), other.data()),
               "HYPRE_IJMatrixSetDiagOffdSizes");
  hypre::check(HYPRE_IJMatrixInitialize(h.matrix), "HYPRE_IJMatrixInitialize");
  hypre::check(
      HYPRE_IJMatrixSetValues(h.matrix, rows_, length.data(), row_ids.data(), inner, K.valuePtr()),
      "HYPRE_IJMatrixSetValues");
  hypre::check(HYPRE_IJMatrixAssemble(h.matrix), "HYPRE_IJMatrixAssemble");
  hypre::check(HYPRE_IJMatrixGetObject(h.matrix, reinterpret_cast<void**>(&h.A)),
               "HYPRE_IJMatrixGetObject");
  SparseMatrixRM().swap(K);  // hypre's copy serves from now on: freed before the hierarchy is built
  for (auto [vector, object] : {std::pair{&h.in, &h.b}, std::pair{&h.out, &h.x}}) {
    hypre::check(HYPRE_IJVectorCreate(MPI_COMM_WORLD, first, last, vector), "HYPRE_IJVectorCreate");
    hypre::check(HYPRE_IJVectorSetObjectType(*vector, HYPRE_PARCSR), "HYPRE_IJVectorSetObjectType");
    hypre::check(HYPRE_IJVectorInitialize(*vector), "HYPRE_IJVectorInitialize");
    hypre::check(HYPRE_IJVectorAssemble(*vector), "HYPRE_IJVectorAssemble");
    hypre::check(HYPRE_IJVectorGetObject(*vector, reinterpret_cast<void**>(object)),
                 "HYPRE_IJVectorGetObject");
  }

  hypre::check(HYPRE_BoomerAMGCreate(&h.amg.h), "HYPRE_BoomerAMGCreate");
  hypre::configure_boomeramg(h.amg.h, row_start.back(), options.block_size,
                             options.nodal_coarsening);
  // hypre's own cycle across the ranks, one V-cycle from zero as a Krylov method's preconditioner:
  // symmetric hybrid Gauss-Seidel (relaxation type 6: Gauss-Seidel within a rank, Jacobi between
  // ranks, forward down and backward up, so the cycle is a symmetric map) and Gaussian elimination
  // on the coarsest level. On the 1e5-particle cylinder, 2 ranks, --tolerance 1e-6 (2026-12-04):
  // type 6 took 44 + 13 CG iterations and 14.5 s, Chebyshev (16) 50 + 15 and 15.6 s, l1-scaled
  // symmetric Gauss-Seidel (8) 303 + 60, l1-Jacobi (18) 1149 + 314.
  HYPRE_BoomerAMGSetRelaxType(h.amg.h, 6);
  HYPRE_BoomerAMGSetCycleRelaxType(h.amg.h, 9, 3);
  HYPRE_BoomerAMGSetNumSweeps(h.amg.h, 1);
  HYPRE_BoomerAMGSetTol(h.amg.h, 0.0);
  HYPRE_BoomerAMGSetMaxIter(h.amg.h, 1);
  hypre::check(HYPRE_BoomerAMGSetup(h.amg.h, h.A, h.b, h.x), "HYPRE_BoomerAMGSetup");
  h.levels = hypre_ParAMGDataNumLevels(reinterpret_cast<hypre_ParAMGData*>(h.amg.h));
}

DistributedAmg::~DistributedAmg() = default;

int DistributedAmg::levels() const {
  return hypre_->levels;
}

void DistributedAmg::apply(const double* r, double* z) const {
  const Hypre& h = *hypre_;
  Eigen::Map<Eigen::VectorXd>(local_data(h.b), rows_) = Eigen::Map<const Eigen::VectorXd>(r, rows_);
  Eigen::Map<Eigen::VectorXd> x(local_data(h.x), rows_);
  x.setZero();
  // One V-cycle: with MaxIter 1 and Tol 0 hypre reports "not converged", which is expected here.
  HYPRE_BoomerAMGSolve(h.amg.h, h.A, h.b, h.x);
  HYPRE_ClearAllErrors();
  Eigen::Map<Eigen::VectorXd>(z, rows_) = x;
}

void DistributedAmg::multiply(const double* in, double* out) const {
  const Hypre& h = *hypre_;
  Eigen::Map<Eigen::VectorXd>(local_data(h.b), rows_) =
      Eigen::Map<const Eigen::VectorXd>(in, rows_);
  hypre::check(HYPRE_ParCSRMatrixMatvec(1.0, h.A, h.b, 0.0, h.x), "HYPRE_ParCSRMatrixMatvec");
  Eigen::Map<Eigen::VectorXd>(out, rows_) =
      Eigen::Map<const Eigen::VectorXd>(local_data(h.x), rows_);
}

}  // namespace bpm
