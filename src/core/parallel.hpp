#pragma once
/// Loops over fewer items than this run serially: for a cantilever of 11 particles the cost of
/// waking a thread team exceeds the work. Results are identical either way.
#include <cstdint>

namespace bpm {
inline constexpr std::int64_t kParallelMinItems = 4096;
}  // namespace bpm
