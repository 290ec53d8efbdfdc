#pragma once
/// Loops over fewer items than this run serially: for a cantilever of 11 particles the cost of
/// waking a thread team exceeds the work. Results are identical either way.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace bpm {
inline constexpr std::int64_t kParallelMinItems = 4096;

/// Deterministic sum of f(i) over [0, n): fixed blocks, each summed in order, block sums in order,
/// so the result does not depend on the number of threads.
template <class F>
double fixed_order_sum(std::int64_t n, const F& f) {
  constexpr std::int64_t kBlock = 4096;
  const std::int64_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial(static_cast<std::size_t>(blocks), 0.0);
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
  for (std::int64_t b = 0; b < blocks; ++b) {
    double s = 0.0;
    for (std::int64_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i)
      s += f(static_cast<std::size_t>(i));
    partial[static_cast<std::size_t>(b)] = s;
  }
  double total = 0.0;
  for (const double s : partial) total += s;
  return total;
}
}  // namespace bpm
