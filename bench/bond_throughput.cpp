// Bond kernel throughput on a simple cubic bonded lattice (see BENCHMARKS.md).
//
// 70^3 = 343,000 steel spheres (R = 1 mm, density 7850 kg/m^3) at spacing 2R, nearest neighbours
// bonded with TBBM (E = 200 GPa, nu = 0.3, r_b = R): 3 * 69 * 70^2 = 1,014,300 bonds. Random tiny
// initial velocities (1e-6 m/s, 1e-3 rad/s) so that every bond carries a load; no damping, no fixed
// DOFs; dt = 0.5 of critical_time_step. The lattice size can be changed with BPMKIT_BENCH_N (e.g. 30
// for profiling under callgrind).
//
// Benchmarks, each at 1 thread and at all cores (the argument is omp_set_num_threads):
//   Step             - the full Simulation::step (kicks, drift, bond update, gather, loads)
//   StepWithProgress - the same with the progress line's monitor installed (its cost: the difference)
//   ProgressCall     - one call of that monitor, printing its line (it is called about every 50 ms)
//   StepSmall        - Simulation::step on a 3^3 lattice (27 particles, 54 bonds), the size of
//                      Chen's cantilevers: every loop runs without a thread team, so this is the
//                      cost of the step's bookkeeping (BENCHMARKS.md, "Page faults and teams of one")
//   UpdateBondLoads  - bpm::update_bond_loads alone
//   GatherBondLoads  - bpm::gather_bond_loads alone
//   StepPacking      - Simulation::step on a generated random packing (bench_packing.hpp: a 1e5-
//                      particle bonded cylinder, bonds only) with its rows as generated, shuffled and
//                      Morton-sorted (issue 12: real inputs are not in lattice order)
//   StepScenario     - the same on the shuffled packing written as CSV files and loaded through
//                      bpm::load_scenario, which stores it in its canonical (Morton) order: a
//                      shuffled file should step as fast as StepPacking's Morton rows
// Counters: bond_updates_per_second (bonds x iterations / wall time) and ns_per_bond.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <random>

#include "bonds/bond_model.hpp"
#include "dem/bond_forces.hpp"
#include "model/model.hpp"
#include "dem/simulation.hpp"
#include "dem/time_step.hpp"
#include "scenario/run_progress.hpp"
#include "scenario/scenario.hpp"

#include "bench_packing.hpp"

namespace {

using bpm::Vec3;

int lattice_size() {
  const char* env = std::getenv("BPMKIT_BENCH_N");
  const int n = env != nullptr ? std::atoi(env) : 70;
  return n > 1 ? n : 70;
}

struct Lattice {
  bpm::Model model;
  double dt = 0.0;
};

std::unique_ptr<Lattice> build_lattice(int n) {
  auto lattice = std::make_unique<Lattice>();
  bpm::Model& model = lattice->model;
  const double radius = 1e-3;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto index = [n](int i, int j, int k) { return static_cast<std::int32_t>((i * n + j) * n + k); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const std::int32_t p = model.particles.add(index(i, j, k), {2.0 * radius * i, 2.0 * radius * j, 2.0 * radius * k},
                                                   radius, 7850.0);
        model.particles.velocity[p] = {1e-6 * u(rng), 1e-6 * u(rng), 1e-6 * u(rng)};
        model.particles.angular_velocity[p] = {1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng)};
      }
    }
  }
  bpm::BondMaterial material;
  material.name = "steel";
  material.model = "tbbm";
  material.youngs_modulus = 200e9;
  material.poisson_ratio = 0.3;
  const double length = 2.0 * radius;
  const bpm::BondConstants constants = bpm::make_bond_constants(material, {radius, length, radius, radius});
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        if (i + 1 < n) model.bonds.add(index(i, j, k), index(i + 1, j, k), constants, radius, length);
        if (j + 1 < n) model.bonds.add(index(i, j, k), index(i, j + 1, k), constants, radius, length);
        if (k + 1 < n) model.bonds.add(index(i, j, k), index(i, j, k + 1), constants, radius, length);
      }
    }
  }
  model.finalize();
  lattice->dt = 0.5 * bpm::critical_time_step(model).critical;
  return lattice;
}

/// Built once, shared by all benchmarks (the state simply keeps evolving).
Lattice& lattice() {
  static const std::unique_ptr<Lattice> instance = build_lattice(lattice_size());
  return *instance;
}

using Clock = std::chrono::steady_clock;

/// bond_updates_per_second is a rate over the benchmark's real time; ns_per_bond is the wall time of
/// the timed loop divided by the bond updates (a plain number, so that it prints without a unit).
void set_counters(benchmark::State& state, std::size_t bonds, Clock::duration elapsed) {
  const double updates = static_cast<double>(bonds) * static_cast<double>(state.iterations());
  state.counters["bond_updates_per_second"] = benchmark::Counter(updates, benchmark::Counter::kIsRate);
  state.counters["ns_per_bond"] = std::chrono::duration<double, std::nano>(elapsed).count() / updates;
  state.counters["bonds"] = static_cast<double>(bonds);
  state.counters["threads"] = static_cast<double>(state.range(0));
}

/// Times whole steps of the lattice: the body of BM_Step and BM_StepWithProgress.
void time_steps(benchmark::State& state, Lattice& l) {
  bpm::Simulation sim(l.model, l.dt);
  const Clock::time_point start = Clock::now();
  for (auto _ : state) {
    sim.step();
    benchmark::ClobberMemory();
  }
  set_counters(state, l.model.bonds.size(), Clock::now() - start);
}

void BM_Step(benchmark::State& state) {
  Lattice& l = lattice();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  time_steps(state, l);
}

void BM_StepSmall(benchmark::State& state) {
  static const std::unique_ptr<Lattice> small = build_lattice(3);
  omp_set_num_threads(static_cast<int>(state.range(0)));
  time_steps(state, *small);
}

/// BM_Step with the progress line installed (scenario/run_progress.hpp), as `bpmkit run` has it on a
/// terminal, written to /dev/null: its cost is the difference to BM_Step.
void BM_StepWithProgress(benchmark::State& state) {
  Lattice& l = lattice();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  std::FILE* sink = std::fopen("/dev/null", "w");
  bpm::RunProgress::Settings settings;
  settings.terminal = true;
  bpm::ProgressPlan plan;
  plan.max_steps = std::int64_t{1} << 40;
  {
    bpm::RunProgress progress(plan, sink, settings);
    const bpm::ScopedStepMonitor watching(progress);
    time_steps(state, l);
  }
  std::fclose(sink);
}

/// One call of the progress monitor, printing its line every time (to /dev/null): the worst case of
/// what BM_StepWithProgress pays about every 50 ms.
void BM_ProgressCall(benchmark::State& state) {
  Lattice& l = lattice();
  std::FILE* sink = std::fopen("/dev/null", "w");
  bpm::RunProgress::Settings settings;
  settings.terminal = true;
  settings.line_interval_s = 0.0;
  bpm::ProgressPlan plan;
  plan.max_steps = std::int64_t{1} << 40;
  {
    bpm::RunProgress progress(plan, sink, settings);
    bpm::Simulation sim(l.model, l.dt);
    for (auto _ : state) benchmark::DoNotOptimize(progress.after_step(sim));
  }
  std::fclose(sink);
}

void BM_UpdateBondLoads(benchmark::State& state) {
  Lattice& l = lattice();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const Clock::time_point start = Clock::now();
  for (auto _ : state) {
    bpm::update_bond_loads(l.model.particles, l.model.bonds, l.dt);
    benchmark::ClobberMemory();
  }
  set_counters(state, l.model.bonds.size(), Clock::now() - start);
}

void BM_GatherBondLoads(benchmark::State& state) {
  Lattice& l = lattice();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const Clock::time_point start = Clock::now();
  for (auto _ : state) {
    bpm::gather_bond_loads(l.model.particles, l.model.bonds);
    benchmark::ClobberMemory();
  }
  set_counters(state, l.model.bonds.size(), Clock::now() - start);
}

const bpm::GeneratedStructure& generated_packing() {
  static const bpm::GeneratedStructure generated = bench::generate_cylinder(100000);
  return generated;
}

/// Tiny random velocities, as on the lattice (every bond loaded); finalises the bonds, sets dt.
void set_in_motion(Lattice& l) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t p = 0; p < l.model.particles.size(); ++p) {
    l.model.particles.velocity[p] = {1e-6 * u(rng), 1e-6 * u(rng), 1e-6 * u(rng)};
    l.model.particles.angular_velocity[p] = {1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng)};
  }
  l.model.finalize();
  l.dt = 0.5 * bpm::critical_time_step(l.model).critical;
}

/// The packing of BM_StepPacking in each row order, built once (the generation once for all three).
Lattice& packing(bench::RowOrder order) {
  static std::unique_ptr<Lattice> built[3];
  std::unique_ptr<Lattice>& l = built[static_cast<int>(order)];
  if (!l) {
    l = std::make_unique<Lattice>();
    l->model = bench::bonded_model(generated_packing(), order);
    set_in_motion(*l);
  }
  return *l;
}

/// The shuffled packing through the files and the scenario reader, built once.
Lattice& scenario_packing() {
  static std::unique_ptr<Lattice> l;
  if (!l) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "bpmkit_bench_scenario";
    l = std::make_unique<Lattice>();
    const auto order = bench::RowOrder::shuffled;
    l->model = bpm::load_scenario(bench::write_scenario(generated_packing(), order, dir)).model;
    std::filesystem::remove_all(dir);
    set_in_motion(*l);
  }
  return *l;
}

void BM_StepPacking(benchmark::State& state) {
  const auto order = static_cast<bench::RowOrder>(state.range(0));
  Lattice& l = packing(order);
  omp_set_num_threads(static_cast<int>(state.range(1)));
  time_steps(state, l);
  state.counters["threads"] = static_cast<double>(state.range(1));
  state.SetLabel(bench::to_string(order));
}

void BM_StepScenario(benchmark::State& state) {
  Lattice& l = scenario_packing();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  time_steps(state, l);
  state.SetLabel("shuffled file, loaded");
}

void orders_and_threads(benchmark::internal::Benchmark* b) {
  b->ArgNames({"order", "threads"});
  for (const int order : {0, 1, 2}) {
    b->Args({order, 1});
    if (omp_get_num_procs() > 1) b->Args({order, omp_get_num_procs()});
  }
}

/// One thread, and all cores if there is more than one.
void thread_counts(benchmark::internal::Benchmark* b) {
  b->ArgName("threads")->Arg(1);
  if (omp_get_num_procs() > 1) b->Arg(omp_get_num_procs());
}

BENCHMARK(BM_Step)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepSmall)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StepWithProgress)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ProgressCall)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UpdateBondLoads)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GatherBondLoads)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepPacking)->Apply(orders_and_threads)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepScenario)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
