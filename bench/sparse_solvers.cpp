// Solve time of the DSM's sparse solvers (src/dsm/sparse_solver.*) on bonded cubic lattices.
//
// n^3 steel spheres (R = 1 mm) at spacing 2R with 10 % position jitter, nearest neighbours bonded
// with TBBM (E = 200 GPa, nu = 0.3, r_b = R); the bottom layer is clamped (its DOFs removed), the
// top layer carries 1 N along x and -2 N along z per particle. 6 DOFs per particle: 6 n^2 (n - 1)
// unknowns (20^3: 45,600; 30^3: 156,600; 40^3: 374,400).
//
// Benchmarks (argument n = 6 ... 40; one solve_spd per iteration, setup included):
//   Cholmod  - supernodal Cholesky (CHOLMOD), by default for n <= 30 only: at n = 40 it needs
//              6.3 GB and 100 s (set BPMKIT_BENCH_CHOLMOD_MAX=40 to run it)
//   AmgPcg   - hypre BoomerAMG-preconditioned CG to a relative residual of 1e-6
// The figures and the choice of SparseSolverOptions::direct_limit are in
// src/solvers/sparse_solver.hpp. Run: ./build/bench/bpmkit_bench_solvers
// [--benchmark_filter='n:(10|20)/'] Counters: unknowns, iterations, relative_residual, peak_MB
// (CHOLMOD's own count of its peak memory) and solver_MB (growth of the process's peak resident set
// over the solves, from /proc/self/status, after resetting the peak: what the solver needs beyond K
// and f, for either solver; MPI's and hypre's one-time start-up is done before and not counted).
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bonds/bond_model.hpp"
#include "model/model.hpp"
#include "solvers/sparse_solver.hpp"
#include "statics/static_assembly.hpp"
#include "statics/static_solver.hpp"

namespace {

struct Problem {
  bpm::SparseMatrixRM K;
  Eigen::VectorXd f;
};

Problem build_problem(int n) {
  const double radius = 1e-3;
  bpm::Model model;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-0.1 * radius, 0.1 * radius);
  auto index = [n](int i, int j, int k) { return static_cast<std::int32_t>((i * n + j) * n + k); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const bpm::Vec3 x{2.0 * radius * i + u(rng), 2.0 * radius * j + u(rng),
                          2.0 * radius * k + u(rng)};
        model.particles.add(index(i, j, k), x, radius, 7850.0);
      }
    }
  }
  bpm::BondMaterial material;
  material.name = "steel";
  material.model = "tbbm";
  material.youngs_modulus = 200e9;
  material.poisson_ratio = 0.3;
  auto bond = [&](std::int32_t a, std::int32_t b) {
    const double length = norm(model.particles.position[b] - model.particles.position[a]);
    model.bonds.add(a, b, bpm::make_bond_constants(material, {radius, length, radius, radius}),
                    radius, length);
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        if (i + 1 < n) bond(index(i, j, k), index(i + 1, j, k));
        if (j + 1 < n) bond(index(i, j, k), index(i, j + 1, k));
        if (k + 1 < n) bond(index(i, j, k), index(i, j, k + 1));
      }
    }
  }
  model.finalize();

  const Eigen::SparseMatrix<double> K_full =
      Eigen::SparseMatrix<double>(bpm::assemble_stiffness(model, 6, {}));
  // Particle (i, j, k) has layer k; the DOFs of layer 0 go, the others keep their order.
  std::vector<Eigen::Index> reduced(static_cast<std::size_t>(K_full.rows()), -1);
  Eigen::Index n_free = 0;
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    if (p % static_cast<std::size_t>(n) == 0) continue;
    for (int k = 0; k < 6; ++k) reduced[6 * p + k] = n_free++;
  }
  Problem problem;
  problem.f = Eigen::VectorXd::Zero(n_free);
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    if (p % static_cast<std::size_t>(n) != static_cast<std::size_t>(n - 1)) continue;
    problem.f[reduced[6 * p]] = 1.0;
    problem.f[reduced[6 * p + 2]] = -2.0;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(K_full.nonZeros()));
  for (Eigen::Index col = 0; col < K_full.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(K_full, col); it; ++it) {
      const Eigen::Index r = reduced[it.row()], c = reduced[it.col()];
      if (r >= 0 && c >= 0) triplets.emplace_back(r, c, it.value());
    }
  }
  problem.K.resize(n_free, n_free);
  problem.K.setFromTriplets(triplets.begin(), triplets.end());
  return problem;
}

/// Built once per size and shared by both solvers.
Problem& problem(int n) {  // not const: solve_spd lends K to hypre
  static std::map<int, Problem> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, build_problem(n)).first;
  return it->second;
}

/// A field of /proc/self/status in MB ("VmRSS": resident now, "VmHWM": peak since the last reset).
double status_megabytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field + ":", 0) == 0)
      return std::stod(line.substr(field.size() + 1)) / 1024.0;  // kB
  }
  return 0.0;
}

/// Resets the peak resident set (VmHWM) to the current one (Linux >= 4.0, /proc/PID/clear_refs).
void reset_peak_memory() {
  // Return the problem builder's freed memory first, so that the solver cannot reuse it unseen.
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
}

void run(benchmark::State& state, bpm::SparseSolverKind kind) {
  const int n = static_cast<int>(state.range(0));
  if (kind == bpm::SparseSolverKind::cholmod) {
    const char* env = std::getenv("BPMKIT_BENCH_CHOLMOD_MAX");
    if (n > (env != nullptr ? std::atoi(env) : 30)) {
      state.SkipWithError("CHOLMOD skipped above BPMKIT_BENCH_CHOLMOD_MAX (default 30)");
      return;
    }
  }
  Problem& p = problem(n);
  bpm::SparseSolverOptions options;
  options.kind = kind;
  if (kind == bpm::SparseSolverKind::amg_pcg) {  // start MPI and hypre outside the measurement
    bpm::SparseMatrixRM one(1, 1);
    one.insert(0, 0) = 1.0;
    Eigen::VectorXd u;
    bpm::solve_spd(one, Eigen::VectorXd::Ones(1), u, options);
  }
  bpm::SparseSolveReport report;
  reset_peak_memory();
  const double resident = status_megabytes("VmRSS");
  for (auto _ : state) {
    Eigen::VectorXd u;
    report = bpm::solve_spd(p.K, p.f, u, options);
    benchmark::DoNotOptimize(u.data());
  }
  state.counters["unknowns"] = static_cast<double>(p.K.rows());
  state.counters["iterations"] = report.iterations;
  state.counters["relative_residual"] = report.relative_residual;
  state.counters["peak_MB"] = static_cast<double>(report.peak_bytes) / 1048576.0;
  state.counters["solver_MB"] = status_megabytes("VmHWM") - resident;
}

void BM_Cholmod(benchmark::State& state) {
  run(state, bpm::SparseSolverKind::cholmod);
}
void BM_AmgPcg(benchmark::State& state) {
  run(state, bpm::SparseSolverKind::amg_pcg);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->ArgName("n");
  for (const int n : {6, 8, 10, 12, 15, 20, 30, 40}) b->Arg(n);
  b->UseRealTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_Cholmod)->Apply(sizes);
BENCHMARK(BM_AmgPcg)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
