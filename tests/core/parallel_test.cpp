// The parallel loops of core/parallel.hpp: every item once, for a team or not, at any size; the
// reductions see every item; the fixed-order sum does not depend on the thread count.
#include "core/parallel.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace {

using bpm::kParallelMinItems;

class ParallelLoops : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    saved_threads_ = omp_get_max_threads();
    omp_set_num_threads(GetParam());
  }
  void TearDown() override { omp_set_num_threads(saved_threads_); }

 private:
  int saved_threads_ = 1;
};

TEST_P(ParallelLoops, EveryItemExactlyOnce) {
  for (const bool team : {false, true}) {
    for (const std::int64_t n : {std::int64_t{0}, std::int64_t{5}, 3 * kParallelMinItems + 7}) {
      std::vector<std::atomic<int>> visits(static_cast<std::size_t>(n));
      bpm::parallel_for(n, team, [&](std::int64_t i) { ++visits[static_cast<std::size_t>(i)]; });
      for (std::int64_t i = 0; i < n; ++i) {
        ASSERT_EQ(visits[static_cast<std::size_t>(i)].load(), 1)
            << "team " << team << ", n " << n << ", item " << i;
      }
    }
  }
}

TEST_P(ParallelLoops, ReductionsSeeEveryItem) {
  const std::int64_t n = 5 * kParallelMinItems + 3;
  // A peak at an item near the end of the loop, and one item that breaks an "and".
  const auto value = [&](std::int64_t i) { return i == n - 2 ? 1e9 : static_cast<double>(i % 97); };
  EXPECT_EQ(
      bpm::parallel_reduce(n, true, 0.0, value, [](double a, double b) { return a > b ? a : b; }),
      1e9);
  EXPECT_FALSE(bpm::parallel_reduce(
      n, true, true, [&](std::int64_t i) { return i != 1234; }, std::logical_and<>()));
  EXPECT_EQ(bpm::parallel_reduce(std::int64_t{3}, true, 0.0, value,
                                 [](double a, double b) { return a > b ? a : b; }),
            2.0);
}

TEST_P(ParallelLoops, FixedOrderSumIsTheSameForAnyThreadCount) {
  const std::int64_t n = 7 * kParallelMinItems + 11;
  const auto f = [](std::size_t i) { return 1.0 / (1.0 + static_cast<double>(i)); };
  const double here = bpm::fixed_order_sum(n, f);
  omp_set_num_threads(1);
  EXPECT_EQ(here, bpm::fixed_order_sum(n, f));
}

INSTANTIATE_TEST_SUITE_P(Threads, ParallelLoops, ::testing::Values(1, 2, 3));

}  // namespace
