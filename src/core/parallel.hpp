#pragma once
/// Parallel loops that skip the thread team for small loops.
///
/// Loops over fewer items than kParallelMinItems run serially: for a cantilever of 11 particles
/// the cost of waking a thread team exceeds the work. This must be a branch around the parallel
/// region, not the `if` clause of `omp parallel`: with the clause libgomp still builds a team of
/// one and wakes a futex when it ends, a system call per loop. On an AMD EPYC VM (2026-12-03)
/// that was 1.4 us per loop, seven loops per step, and tripled the cantilever suite's wall time.
/// Results are identical either way.
///
/// Every loop runs over ranges (parallel_ranges), and the per-item body is flattened into the
/// range's loop (`flatten`): without it GCC did not inline a large body (the contact loop) called
/// from both the team's loop and the serial one, and a call per item made it 18 % slower (ranges
/// alone did not change that).
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace bpm {
inline constexpr std::int64_t kParallelMinItems = 4096;

/// body(begin, end) over consecutive ranges covering [0, n): one per thread of the team when
/// `team`, else [0, n) on this thread.
template <class RangeBody>
void parallel_ranges(std::int64_t n, bool team, const RangeBody& body) {
  if (!team) {
    body(std::int64_t{0}, n);
    return;
  }
#pragma omp parallel
  {
    const std::int64_t threads = omp_get_num_threads(), t = omp_get_thread_num();
    body(n * t / threads, n * (t + 1) / threads);
  }
}

/// combine over the results of body(begin, end) for consecutive ranges covering [0, n), as
/// parallel_ranges splits them; `combine` must not care about order (see parallel_reduce).
template <class T, class RangeBody, class Combine>
T parallel_reduce_ranges(std::int64_t n, bool team, T init, const RangeBody& body, const Combine& combine) {
  if (!team) return combine(init, body(std::int64_t{0}, n));
  T result = init;
#pragma omp parallel
  {
    const std::int64_t threads = omp_get_num_threads(), t = omp_get_thread_num();
    const T local = body(n * t / threads, n * (t + 1) / threads);
#pragma omp critical(bpm_parallel_reduce_ranges)
    result = combine(result, local);
  }
  return result;
}

/// body(i) for every i in [0, n): on the thread team when `team`, else here.
template <class Body>
void parallel_for(std::int64_t n, bool team, const Body& body) {
  parallel_ranges(n, team, [&](std::int64_t begin, std::int64_t end) __attribute__((flatten)) {
    for (std::int64_t i = begin; i < end; ++i) body(i);
  });
}

/// body(i) for every i in [0, n), with a team when n exceeds kParallelMinItems.
template <class Body>
void parallel_for(std::int64_t n, const Body& body) {
  parallel_for(n, n > kParallelMinItems, body);
}

/// combine(... combine(init, body(0)) ..., body(n - 1)), every body(i) evaluated once (bodies
/// may have side effects). The per-thread results are combined in no fixed order, so `combine`
/// must not care about order: max, min, and, or. Sums that must not depend on the thread count
/// use fixed_order_sum.
template <class T, class Body, class Combine>
T parallel_reduce(std::int64_t n, bool team, T init, const Body& body, const Combine& combine) {
  return parallel_reduce_ranges(n, team, init, [&](std::int64_t begin, std::int64_t end) __attribute__((flatten)) {
    T local = init;
    for (std::int64_t i = begin; i < end; ++i) local = combine(local, body(i));
    return local;
  }, combine);
}

template <class T, class Body, class Combine>
T parallel_reduce(std::int64_t n, T init, const Body& body, const Combine& combine) {
  return parallel_reduce(n, n > kParallelMinItems, init, body, combine);
}

/// Deterministic sum of f(i) over [0, n): fixed blocks, each summed in order, block sums in order,
/// so the result does not depend on the number of threads.
template <class F>
double fixed_order_sum(std::int64_t n, const F& f) {
  constexpr std::int64_t kBlock = 4096;
  const std::int64_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial(static_cast<std::size_t>(blocks), 0.0);
  parallel_for(blocks, n >= kParallelMinItems, [&](std::int64_t b) {
    double s = 0.0;
    for (std::int64_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i)
      s += f(static_cast<std::size_t>(i));
    partial[static_cast<std::size_t>(b)] = s;
  });
  double total = 0.0;
  for (const double s : partial) total += s;
  return total;
}
}  // namespace bpm
