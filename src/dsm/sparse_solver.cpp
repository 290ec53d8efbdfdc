#include "dsm/sparse_solver.hpp"

// hypre's MPI: the C API only (OpenMPI's deprecated C++ bindings would need libmpi_cxx).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dsm/cholmod_factor.hpp"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define BPM_LEAK_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#include <sanitizer/lsan_interface.h>
#define BPM_LEAK_SANITIZER 1
#endif
#endif

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

/// ||f - K u|| / ||f|| (||f - K u|| if f = 0). Eigen runs the row-major product on OpenMP threads.
double relative_residual(const SparseMatrixRM& K, const Eigen::VectorXd& f,
                         const Eigen::VectorXd& u) {
  const double r = (f - K * u).norm();
  const double scale = f.norm();
  return scale > 0.0 ? r / scale : r;
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
// hypre BoomerAMG + PCG

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
bool mpi_started_here = false;  // set once, under start_hypre's guard

void stop_hypre() {
  [[maybe_unused]] const UntrackedAllocations untracked;
  HYPRE_Finalize();
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (mpi_started_here && finalized == 0) MPI_Finalize();
}

void start_hypre() {
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
    std::atexit(stop_hypre);
    return true;
  }();
  (void)started;
}

void check_hypre(HYPRE_Int error, const char* call) {
  if (error == 0) return;
  char description[256] = {};
  HYPRE_DescribeError(error, description);
  HYPRE_ClearAllErrors();
  throw std::runtime_error(std::string("hypre: ") + call + " failed: " + description);
}

// Owners of the hypre objects (destroyed in reverse order: solvers before the matrix and vectors).
struct IJMatrix {
  HYPRE_IJMatrix h = nullptr;
  ~IJMatrix() {
    if (h != nullptr) HYPRE_IJMatrixDestroy(h);
  }
};
struct IJVector {
  HYPRE_IJVector h = nullptr;
  ~IJVector() {
    if (h != nullptr) HYPRE_IJVectorDestroy(h);
  }
};
struct BoomerAMG {
  HYPRE_Solver h = nullptr;
  ~BoomerAMG() {
    if (h != nullptr) HYPRE_BoomerAMGDestroy(h);
  }
};
struct ParCSRPCG {
  HYPRE_Solver h = nullptr;
  ~ParCSRPCG() {
    if (h != nullptr) HYPRE_ParCSRPCGDestroy(h);
  }
};

static_assert(sizeof(HYPRE_Int) == sizeof(int) && sizeof(HYPRE_BigInt) == sizeof(int),
              "hypre with 32-bit indices, like the int-indexed Eigen matrix");

/// 0, 1, ..., n - 1: the global numbers of the rows (and vector entries), all on this process.
std::vector<HYPRE_BigInt> row_numbers(HYPRE_Int n) {
  std::vector<HYPRE_BigInt> rows(static_cast<std::size_t>(n));
  std::iota(rows.begin(), rows.end(), 0);
  return rows;
}

/// hypre's copy of K (compressed, rows numbered as `rows`). One process owns every row
/// (MPI_COMM_SELF: also right if the program runs under mpirun), so the whole matrix goes in with
/// one SetValues call, into rows sized beforehand. Returns A's ParCSR matrix (owned by A).
HYPRE_ParCSRMatrix make_matrix(IJMatrix& A, const SparseMatrixRM& K,
                               const std::vector<HYPRE_BigInt>& rows) {
  const auto n = static_cast<HYPRE_Int>(rows.size());
  std::vector<HYPRE_Int> row_sizes(static_cast<std::size_t>(n));
  for (HYPRE_Int r = 0; r < n; ++r) row_sizes[r] = K.outerIndexPtr()[r + 1] - K.outerIndexPtr()[r];
  check_hypre(HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, n - 1, 0, n - 1, &A.h),
              "HYPRE_IJMatrixCreate");
  check_hypre(HYPRE_IJMatrixSetObjectType(A.h, HYPRE_PARCSR), "HYPRE_IJMatrixSetObjectType");
  check_hypre(HYPRE_IJMatrixSetRowSizes(A.h, row_sizes.data()), "HYPRE_IJMatrixSetRowSizes");
  check_hypre(HYPRE_IJMatrixInitialize(A.h), "HYPRE_IJMatrixInitialize");
  check_hypre(HYPRE_IJMatrixSetValues(A.h, n, row_sizes.data(), rows.data(), K.innerIndexPtr(),
                                      K.valuePtr()),
              "HYPRE_IJMatrixSetValues");
  check_hypre(HYPRE_IJMatrixAssemble(A.h), "HYPRE_IJMatrixAssemble");
  HYPRE_ParCSRMatrix parcsr = nullptr;
  check_hypre(HYPRE_IJMatrixGetObject(A.h, reinterpret_cast<void**>(&parcsr)),
              "HYPRE_IJMatrixGetObject");
  return parcsr;
}

/// A vector with entries `rows`, set to `values`. Returns its ParVector (owned by v).
HYPRE_ParVector make_vector(IJVector& v, const std::vector<HYPRE_BigInt>& rows,
                            const double* values) {
  const auto n = static_cast<HYPRE_Int>(rows.size());
  check_hypre(HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &v.h), "HYPRE_IJVectorCreate");
  check_hypre(HYPRE_IJVectorSetObjectType(v.h, HYPRE_PARCSR), "HYPRE_IJVectorSetObjectType");
  check_hypre(HYPRE_IJVectorInitialize(v.h), "HYPRE_IJVectorInitialize");
  check_hypre(HYPRE_IJVectorSetValues(v.h, n, rows.data(), values), "HYPRE_IJVectorSetValues");
  check_hypre(HYPRE_IJVectorAssemble(v.h), "HYPRE_IJVectorAssemble");
  HYPRE_ParVector par = nullptr;
  check_hypre(HYPRE_IJVectorGetObject(v.h, reinterpret_cast<void**>(&par)),
              "HYPRE_IJVectorGetObject");
  return par;
}

/// BoomerAMG settings, measured with bench/sparse_solvers.cpp on clamped, top-loaded TBBM cubic
/// lattices (6 DOF, 45,600 and 156,600 unknowns) and on a generated random packing (15,455
/// particles, 86,802 unknowns), tolerance 1e-6:
/// - systems AMG, unknown-based (num_functions = block_size, nodal = 0): the packing needs 38
///   PCG iterations, 93 without num_functions; nodal coarsening (norms 1, 4, 6) took 13-65 % more
///   iterations and 20-60 % more time, as a block norm mixes force/m and moment/rad entries that
///   are ~r^2 apart;
/// - HMIS coarsening, ext+i interpolation (at most 4 entries a row), one level of aggressive
///   coarsening with multipass interpolation: without it the setup took 1.6-2x as long and the
///   lattices 1.5-1.7x overall (the packing: 26 instead of 38 iterations, 1.1x overall); 2-stage
///   ext+i on that level took 60 iterations on the packing;
/// - strong threshold 0.6: 0.5 to 0.8 were within the noise (20-22 iterations on the lattices,
///   38-41 on the packing); 0.25 took 27 on the lattice, 0.9 took 28;
/// - hypre's default smoother (l1-Gauss-Seidel forward down, backward up: symmetric, as PCG needs)
///   beat symmetric l1-GS (8) and hybrid symmetric GS (6), which save 1-6 iterations for a
///   costlier sweep (20-60 % slower overall); l1-Jacobi (18) took 180 iterations.
/// The lattices need 15-22 iterations from 1,080 to 374,400 unknowns.
void configure_boomeramg(HYPRE_Solver amg, HYPRE_Int n, int block_size) {
  HYPRE_BoomerAMGSetPrintLevel(amg, 0);
  HYPRE_BoomerAMGSetMaxIter(amg, 1);  // one V-cycle per PCG iteration
  HYPRE_BoomerAMGSetTol(amg, 0.0);
  HYPRE_BoomerAMGSetCoarsenType(amg, 10);  // HMIS
  HYPRE_BoomerAMGSetInterpType(amg, 6);    // extended+i
  HYPRE_BoomerAMGSetPMaxElmts(amg, 4);
  HYPRE_BoomerAMGSetAggNumLevels(amg, 1);
  HYPRE_BoomerAMGSetAggInterpType(amg, 4);  // multipass
  HYPRE_BoomerAMGSetStrongThreshold(amg, 0.6);
  if (block_size > 1 && n % block_size == 0) {
    HYPRE_BoomerAMGSetNumFunctions(amg, block_size);
    HYPRE_BoomerAMGSetNodal(amg, 0);
  }
}

SparseSolveReport solve_amg_pcg(const SparseMatrixRM& K, const Eigen::VectorXd& f,
                                Eigen::VectorXd& u, const SparseSolverOptions& options) {
  start_hypre();
  const auto start = Clock::now();
  const auto n = static_cast<HYPRE_Int>(K.rows());
  const std::vector<HYPRE_BigInt> rows = row_numbers(n);
  IJMatrix A;
  const HYPRE_ParCSRMatrix parcsr_A = make_matrix(A, K, rows);
  if (u.size() != K.rows()) u = Eigen::VectorXd::Zero(K.rows());
  IJVector b, x;
  const HYPRE_ParVector par_b = make_vector(b, rows, f.data());
  const HYPRE_ParVector par_x = make_vector(x, rows, u.data());

  BoomerAMG amg;
  check_hypre(HYPRE_BoomerAMGCreate(&amg.h), "HYPRE_BoomerAMGCreate");
  configure_boomeramg(amg.h, n, options.block_size);
  ParCSRPCG pcg;
  check_hypre(HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &pcg.h), "HYPRE_ParCSRPCGCreate");
  HYPRE_PCGSetTol(pcg.h, options.tolerance);  // ||r|| <= tol ||f||
  HYPRE_PCGSetTwoNorm(pcg.h, 1);
  HYPRE_PCGSetMaxIter(pcg.h, options.max_iterations);
  HYPRE_PCGSetPrintLevel(pcg.h, 0);
  HYPRE_ParCSRPCGSetPrecond(pcg.h, HYPRE_BoomerAMGSolve, HYPRE_BoomerAMGSetup, amg.h);
  check_hypre(HYPRE_ParCSRPCGSetup(pcg.h, parcsr_A, par_b, par_x), "HYPRE_ParCSRPCGSetup");

  SparseSolveReport report;
  report.used = SparseSolverKind::amg_pcg;
  std::vector<double> values(static_cast<std::size_t>(n));
  // PCG stops on its recursively updated residual, which can drift from the true one. If the true
  // residual misses the tolerance, go on from the current iterate (hypre's criterion is relative to
  // ||f||, not to the restart's residual).
  for (int attempt = 0; attempt < 3; ++attempt) {
    // A missed tolerance sets hypre's error flag; the true residual decides below.
    HYPRE_ParCSRPCGSolve(pcg.h, parcsr_A, par_b, par_x);
    HYPRE_ClearAllErrors();
    HYPRE_Int iterations = 0;
    HYPRE_ParCSRPCGGetNumIterations(pcg.h, &iterations);
    report.iterations += iterations;
    check_hypre(HYPRE_IJVectorGetValues(x.h, n, rows.data(), values.data()),
                "HYPRE_IJVectorGetValues");
    u = Eigen::Map<const Eigen::VectorXd>(values.data(), n);
    report.relative_residual = relative_residual(K, f, u);
    if (report.relative_residual <= options.tolerance || !std::isfinite(report.relative_residual) ||
        report.iterations >= options.max_iterations) {
      break;
    }
  }
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

SparseSolveReport solve_spd(const SparseMatrixRM& K, const Eigen::VectorXd& f, Eigen::VectorXd& u,
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
  // Both solvers read K's arrays in place, which must be compressed (they are unless insert()).
  SparseMatrixRM compressed;
  const SparseMatrixRM* A = &K;
  if (!K.isCompressed()) {
    compressed = K;
    compressed.makeCompressed();
    A = &compressed;
  }
  if (kind == SparseSolverKind::cholmod) return solve_cholmod(*A, f, u);
  return solve_amg_pcg(*A, f, u, options);
}

// ---------------------------------------------------------------------------------------------
// SpdPreconditioner

/// hypre's copy of K, the BoomerAMG hierarchy set up on it, and the right-hand side and solution
/// vectors, reused by every apply. Members are destroyed in reverse order: the solver first.
struct SpdPreconditioner::Amg {
  std::vector<HYPRE_BigInt> rows;
  IJMatrix A;
  IJVector b, x;
  BoomerAMG amg;
  HYPRE_ParCSRMatrix parcsr_A = nullptr;
  HYPRE_ParVector par_b = nullptr, par_x = nullptr;

  Amg(const SparseMatrixRM& K, int block_size) {
    start_hypre();
    const auto n = static_cast<HYPRE_Int>(K.rows());
    rows = row_numbers(n);
    parcsr_A = make_matrix(A, K, rows);
    const std::vector<double> zero(static_cast<std::size_t>(n), 0.0);
    par_b = make_vector(b, rows, zero.data());
    par_x = make_vector(x, rows, zero.data());
    check_hypre(HYPRE_BoomerAMGCreate(&amg.h), "HYPRE_BoomerAMGCreate");
    configure_boomeramg(amg.h, n, block_size);  // one V-cycle per solve, tolerance 0
    check_hypre(HYPRE_BoomerAMGSetup(amg.h, parcsr_A, par_b, par_x), "HYPRE_BoomerAMGSetup");
  }

  /// One V-cycle from z = 0 on K z = r: a fixed linear map of r.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
    const auto n = static_cast<HYPRE_Int>(rows.size());
    check_hypre(HYPRE_IJVectorSetValues(b.h, n, rows.data(), r.data()), "HYPRE_IJVectorSetValues");
    check_hypre(HYPRE_ParVectorSetConstantValues(par_x, 0.0), "HYPRE_ParVectorSetConstantValues");
    check_hypre(HYPRE_BoomerAMGSolve(amg.h, parcsr_A, par_b, par_x), "HYPRE_BoomerAMGSolve");
    z.resize(n);
    check_hypre(HYPRE_IJVectorGetValues(x.h, n, rows.data(), z.data()), "HYPRE_IJVectorGetValues");
  }
};

SpdPreconditioner::SpdPreconditioner(const SparseMatrixRM& K, const SparseSolverOptions& options)
    : kind_(chosen_solver(K, options)), size_(K.rows()) {
  if (K.rows() != K.cols()) {
    throw std::invalid_argument("SpdPreconditioner: K is " + std::to_string(K.rows()) + "x" +
                                std::to_string(K.cols()));
  }
  if (K.rows() == 0) return;
  // Both read K's arrays in place, which must be compressed; a compressed copy lives only while
  // the preconditioner is built.
  SparseMatrixRM compressed;
  const SparseMatrixRM* A = &K;
  if (!K.isCompressed()) {
    compressed = K;
    compressed.makeCompressed();
    A = &compressed;
  }
  if (kind_ == SparseSolverKind::cholmod) {
    cholmod_ = std::make_unique<CholmodFactor>(*A);
  } else {
    amg_ = std::make_unique<Amg>(*A, options.block_size);
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
    amg_->apply(r, z);
  }
}

}  // namespace bpm
