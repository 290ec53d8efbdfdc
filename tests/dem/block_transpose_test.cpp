// The AVX-512 shuffles that move rows into the bond kernel's blocks and back
// (dem/block_transpose.hpp) against plain element copies: every component of every lane must land
// where the copy puts it, bit for bit, and the last row of an array must be readable. Skipped on
// targets without AVX-512 (the kernel then uses the plain copies).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "dem/block_transpose.hpp"

namespace bpm {
namespace {

#if defined(BPMKIT_BLOCK_TRANSPOSE)
namespace bt = block_transpose;

/// Distinct values, so a component in the wrong lane or slot cannot go unnoticed.
std::vector<Vec3> numbered_rows(std::size_t count) {
  std::vector<Vec3> rows(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto base = 1000.0 * static_cast<double>(i);
    rows[i] = {base + 1.0, base + 2.0, base + 3.0};
  }
  return rows;
}

TEST(BlockTranspose, RowsByIndexLandInTheirLanes) {
  // Exactly 17 rows, no spare capacity, and the last row among the indices: a full 32-byte load of
  // it would read past the array (ASan and the masked load must both be content).
  const std::vector<Vec3> rows = numbered_rows(17);
  const std::int32_t index[8] = {16, 0, 5, 5, 11, 2, 16, 9};
  __m256d r[8];
  for (int k = 0; k < 8; ++k) r[k] = bt::row(rows.data(), index[k]);
  alignas(64) bt::Components c;
  bt::rows_to_components(r, c);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(c[0][k], rows[index[k]].x) << "lane " << k;
    EXPECT_EQ(c[1][k], rows[index[k]].y) << "lane " << k;
    EXPECT_EQ(c[2][k], rows[index[k]].z) << "lane " << k;
  }
}

TEST(BlockTranspose, ConsecutiveRowsRoundTrip) {
  const std::vector<Vec3> rows = numbered_rows(11);
  for (std::size_t first : {0u, 3u}) {  // unaligned starts too
    alignas(64) bt::Components c;
    bt::aos_to_components(rows.data() + first, c);
    for (int k = 0; k < 8; ++k) {
      EXPECT_EQ(c[0][k], rows[first + k].x) << "lane " << k;
      EXPECT_EQ(c[1][k], rows[first + k].y) << "lane " << k;
      EXPECT_EQ(c[2][k], rows[first + k].z) << "lane " << k;
    }
    // Back into rows between two untouched guards.
    std::vector<Vec3> out(10, Vec3{-1.0, -2.0, -3.0});
    bt::components_to_aos(c, out.data() + 1);
    for (int k = 0; k < 8; ++k) {
      EXPECT_EQ(out[1 + k].x, rows[first + k].x) << "row " << k;
      EXPECT_EQ(out[1 + k].y, rows[first + k].y) << "row " << k;
      EXPECT_EQ(out[1 + k].z, rows[first + k].z) << "row " << k;
    }
    EXPECT_EQ(out[0].z, -3.0);
    EXPECT_EQ(out[9].x, -1.0);
  }
}

TEST(BlockTranspose, StiffnessRowsLandInTheirArrays) {
  std::vector<BondStiffness> rows(9);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto base = 10.0 * static_cast<double>(i);
    rows[i] = {base + 1.0, base + 2.0, base + 3.0, base + 4.0};
  }
  alignas(64) double k_n[8], k_s[8], k_tor[8], k_ben[8];
  bt::stiffness_to_components(rows.data() + 1, k_n, k_s, k_tor, k_ben);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(k_n[k], rows[1 + k].k_n) << "lane " << k;
    EXPECT_EQ(k_s[k], rows[1 + k].k_s) << "lane " << k;
    EXPECT_EQ(k_tor[k], rows[1 + k].k_tor) << "lane " << k;
    EXPECT_EQ(k_ben[k], rows[1 + k].k_ben) << "lane " << k;
  }
}
#else
TEST(BlockTranspose, NotCompiledWithoutAvx512) {
  GTEST_SKIP() << "target has no AVX-512F/VL";
}
#endif

}  // namespace
}  // namespace bpm
