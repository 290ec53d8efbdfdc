// Memory bandwidth of this machine, the ceiling the DEM passes are judged against: a loop that
// streams its arrays cannot beat these figures (BENCHMARKS.md, the section "The compression step
// against b4f39c4 side by side; the machine's bandwidth ...").
//
//   StreamRead   - s += b[i] + c[i]: reads only
//   StreamTriad  - a[i] = b[i] + 1.5 c[i]: two reads and one write per element, as the bond and
//                  contact loops read their state and write their loads
// Arrays of 2^25 doubles (256 MiB each), far beyond any L3. Counters: bytes_per_second counts the
// bytes the loop names (16 per element read, 24 per triad element); a write also reads its line
// first (write-allocate), so the memory moves 32 bytes per triad element.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstdint>
#include <vector>

namespace {

constexpr std::int64_t kElements = std::int64_t{1} << 25;

struct Arrays {
  std::vector<double> a, b, c;
  Arrays()
      : a(static_cast<std::size_t>(kElements), 1.0),
        b(static_cast<std::size_t>(kElements), 2.0),
        c(static_cast<std::size_t>(kElements), 3.0) {}
};

Arrays& arrays() {
  static Arrays instance;
  return instance;
}

void BM_StreamRead(benchmark::State& state) {
  Arrays& m = arrays();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const double* b = m.b.data();
  const double* c = m.c.data();
  for (auto _ : state) {
    double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum)
    for (std::int64_t i = 0; i < kElements; ++i) sum += b[i] + c[i];
    benchmark::DoNotOptimize(sum);
  }
  state.SetBytesProcessed(state.iterations() * kElements * 16);
}

void BM_StreamTriad(benchmark::State& state) {
  Arrays& m = arrays();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  double* a = m.a.data();
  const double* b = m.b.data();
  const double* c = m.c.data();
  for (auto _ : state) {
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < kElements; ++i) a[i] = b[i] + 1.5 * c[i];
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(state.iterations() * kElements * 24);
}

void thread_counts(benchmark::internal::Benchmark* b) {
  b->ArgName("threads");
  b->Arg(1);
  if (omp_get_num_procs() > 1) b->Arg(omp_get_num_procs());
}

BENCHMARK(BM_StreamRead)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StreamTriad)->Apply(thread_counts)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
