#include "solvers/hypre_support.hpp"

#include <_hypre_parcsr_mv.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define BPM_LEAK_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#include <sanitizer/lsan_interface.h>
#define BPM_LEAK_SANITIZER 1
#endif
#endif

namespace bpm::hypre {
namespace {

static_assert(sizeof(HYPRE_Int) == sizeof(int) && sizeof(HYPRE_BigInt) == sizeof(int) &&
                  sizeof(HYPRE_Complex) == sizeof(double),
              "hypre with 32-bit indices and real doubles, like the int-indexed Eigen matrix");

/// OpenMPI frees only part of what MPI_Init allocates, and unloads its plugins (mca_*.so) at
/// MPI_Finalize, before LeakSanitizer runs at exit: the plugins' frames are then unnamed, and
/// scripts/lsan.supp cannot match them. So the leak checker (sanitizer builds) does not track this
/// thread's allocations while MPI and hypre start and stop.
struct UntrackedAllocations {
#ifdef BPM_LEAK_SANITIZER
  UntrackedAllocations() {
    __lsan_disable();
  }
  ~UntrackedAllocations() {
    __lsan_enable();
  }
  UntrackedAllocations(const UntrackedAllocations&) = delete;
  UntrackedAllocations& operator=(const UntrackedAllocations&) = delete;
#endif
};

/// hypre is built with MPI: MPI and hypre start once per process, on first use, and stop at exit.
/// A program that started MPI itself keeps it (and finalises it). Without mpirun MPI starts as a
/// singleton: about 0.4 s per process for the start and the stop.
bool mpi_started_here = false;  // set once, under start's guard

void stop() {
  [[maybe_unused]] const UntrackedAllocations untracked;
  HYPRE_Finalize();
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (mpi_started_here && finalized == 0) MPI_Finalize();
}

/// Moves each row's diagonal entry to the front of the row (hypre's ParCSR convention), shifting
/// the entries before it by one; the others keep their (sorted) order. Rows are independent. K is
/// checked before anything moves, so a throw leaves it as it was.
void diagonal_first(SparseMatrixRM& K) {
  const int* outer = K.outerIndexPtr();
  int* columns = K.innerIndexPtr();
  double* values = K.valuePtr();
  const auto rows = static_cast<int>(K.rows());
  auto diagonal = [&](int r) {
    return std::lower_bound(columns + outer[r], columns + outer[r + 1], r);
  };
  bool missing = false;
#pragma omp parallel for schedule(static) reduction(|| : missing)
  for (int r = 0; r < rows; ++r) {
    const int* at = diagonal(r);
    missing = missing || at == columns + outer[r + 1] || *at != r;
  }
  if (missing) {
    throw std::invalid_argument("hypre::BorrowedMatrix: a diagonal entry of K is not stored");
  }
#pragma omp parallel for schedule(static)
  for (int r = 0; r < rows; ++r) {
    const auto k = diagonal(r) - (columns + outer[r]);
    std::rotate(columns + outer[r], columns + outer[r] + k, columns + outer[r] + k + 1);
    std::rotate(values + outer[r], values + outer[r] + k, values + outer[r] + k + 1);
  }
}

/// The inverse of diagonal_first: each row's first entry (its diagonal) goes back between the
/// entries with smaller and larger column numbers.
void diagonal_in_order(SparseMatrixRM& K) {
  const int* outer = K.outerIndexPtr();
  int* columns = K.innerIndexPtr();
  double* values = K.valuePtr();
  const auto rows = static_cast<int>(K.rows());
#pragma omp parallel for schedule(static)
  for (int r = 0; r < rows; ++r) {
    int* const begin = columns + outer[r];
    int* const end = columns + outer[r + 1];
    if (begin == end) continue;
    int* const to = std::lower_bound(begin + 1, end, r);
    const auto k = to - begin;
    std::rotate(begin, begin + 1, to);
    std::rotate(values + outer[r], values + outer[r] + 1, values + outer[r] + k);
  }
}

}  // namespace

void start() {
  static const bool started = [] {
    [[maybe_unused]] const UntrackedAllocations untracked;
    int mpi_ready = 0;
    MPI_Initialized(&mpi_ready);
    if (mpi_ready == 0) {
      int provided = 0;
      // Only this thread calls MPI (through hypre).
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
      mpi_started_here = true;
    }
    HYPRE_Init();
    std::atexit(stop);
    return true;
  }();
  (void)started;
}

/// BoomerAMG settings for the hierarchy, measured on the case 1 cylinder (98,773 particles,
/// 592,638 unknowns) with this cycle and on the solver benchmark's lattices: systems AMG with
/// unknown-based coarsening (num_functions = block_size; nodal coarsening took 13-65 % more
/// iterations, as a block norm mixes N/m and N/rad entries ~r^2 apart), PMIS coarsening with one
/// level of aggressive coarsening (multipass interpolation), extended+i interpolation with at most
/// 4 entries a row, strong threshold 0.6. On case 1: 27 CG iterations and a 3.1-3.7 s set-up;
/// HMIS took 26 iterations but a 3.9-4.1 s set-up (the set-up runs on one core, an iteration on
/// all); two aggressive levels (33 iterations), P_max 2 or 3 (30, 28) and threshold 0.7 (29) were
/// slower overall. hypre's smoother is not used: Jacobi (relaxation type 0) needs no set-up.
/// `nodal` (nodal coarsening 1: a particle's block's Frobenius norm as its strength, interpolation
/// still by unknown) suits the DSM with walls, whose CG deflates the rigid modes: there its first
/// coarse level has 22,608 rows and 2.7 M entries instead of 78,898 and 8.3 M, for the same 26 CG
/// iterations (with HMIS 24, but a Newton step less moved K by 1e-5; P_max 2: 27; NodalDiag 1 or
/// 2: 26). Without the deflation nodal 1, 4 and 6 took 46, 53 and 57 iterations against 45
/// (2026-12-03).
void configure_boomeramg(HYPRE_Solver amg, HYPRE_Int n, int block_size, bool nodal) {
  HYPRE_BoomerAMGSetPrintLevel(amg, 0);
  HYPRE_BoomerAMGSetCoarsenType(amg, 8);  // PMIS
  HYPRE_BoomerAMGSetInterpType(amg, 6);   // extended+i
  HYPRE_BoomerAMGSetPMaxElmts(amg, 4);
  HYPRE_BoomerAMGSetAggNumLevels(amg, 1);
  HYPRE_BoomerAMGSetAggInterpType(amg, 4);  // multipass
  HYPRE_BoomerAMGSetStrongThreshold(amg, 0.6);
  HYPRE_BoomerAMGSetRelaxType(amg, 0);
  if (block_size > 1 && n % block_size == 0) {
    HYPRE_BoomerAMGSetNumFunctions(amg, block_size);
    HYPRE_BoomerAMGSetNodal(amg, nodal ? 1 : 0);
  }
}

void check(HYPRE_Int error, const char* call) {
  if (error == 0) return;
  char description[256] = {};
  HYPRE_DescribeError(error, description);
  HYPRE_ClearAllErrors();
  throw std::runtime_error(std::string("hypre: ") + call + " failed: " + description);
}

// ---------------------------------------------------------------------------------------------

BorrowedMatrix::BorrowedMatrix(SparseMatrixRM& K) : K_(K) {
  if (K.rows() != K.cols() || !K.isCompressed()) {
    throw std::invalid_argument("hypre::BorrowedMatrix: K must be square and compressed");
  }
  start();
  diagonal_first(K);
  const auto n = static_cast<HYPRE_BigInt>(K.rows());
  HYPRE_BigInt starts[2] = {0, n};  // copied by hypre
  matrix_ = hypre_ParCSRMatrixCreate(MPI_COMM_SELF, n, n, starts, starts, 0, 0, 0);
  // The local block holds every entry; hypre must not free K's arrays (owns_data = 0).
  hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(matrix_);
  hypre_CSRMatrixI(diag) = K.outerIndexPtr();
  hypre_CSRMatrixJ(diag) = K.innerIndexPtr();
  hypre_CSRMatrixData(diag) = K.valuePtr();
  hypre_CSRMatrixNumNonzeros(diag) = static_cast<HYPRE_Int>(K.nonZeros());
  hypre_CSRMatrixOwnsData(diag) = 0;
  hypre_CSRMatrixMemoryLocation(diag) = HYPRE_MEMORY_HOST;
  hypre_CSRMatrixSetRownnz(diag);
  // No other process: an empty off-process block (row pointers all zero).
  hypre_CSRMatrixInitialize_v2(hypre_ParCSRMatrixOffd(matrix_), 0, HYPRE_MEMORY_HOST);
  hypre_ParCSRMatrixSetNumNonzeros(matrix_);
  hypre_ParCSRMatrixSetDNumNonzeros(matrix_);
}

BorrowedMatrix::~BorrowedMatrix() {
  // hypre frees a block's row pointers whatever owns_data says: hand K's arrays back first.
  hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(matrix_);
  hypre_CSRMatrixI(diag) = nullptr;
  hypre_CSRMatrixJ(diag) = nullptr;
  hypre_CSRMatrixData(diag) = nullptr;
  hypre_ParCSRMatrixDestroy(matrix_);
  diagonal_in_order(K_);
}

HYPRE_ParCSRMatrix BorrowedMatrix::get() const {
  return matrix_;
}

BorrowedVector::BorrowedVector(Eigen::VectorXd& v) {
  start();
  const auto n = static_cast<HYPRE_BigInt>(v.size());
  HYPRE_BigInt starts[2] = {0, n};
  vector_ = hypre_ParVectorCreate(MPI_COMM_SELF, n, starts);
  hypre_Vector* local = hypre_ParVectorLocalVector(vector_);
  hypre_VectorData(local) = v.data();
  hypre_VectorOwnsData(local) = 0;
  hypre_VectorMemoryLocation(local) = HYPRE_MEMORY_HOST;
  hypre_ParVectorActualLocalSize(vector_) = static_cast<HYPRE_Int>(n);
}

BorrowedVector::~BorrowedVector() {
  hypre_VectorData(hypre_ParVectorLocalVector(vector_)) = nullptr;
  hypre_ParVectorDestroy(vector_);
}

HYPRE_ParVector BorrowedVector::get() const {
  return vector_;
}

}  // namespace bpm::hypre
