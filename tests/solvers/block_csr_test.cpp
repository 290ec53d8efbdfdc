// BlockCsr (src/dsm/block_csr.*): products by dense blocks equal the CSR loop's bit for bit, on
// matrices whose blocks are partly stored (pruned zeros, a row with only its diagonal); matrices
// that are not block-structured are left to CSR; conjugate gradients reads the K of a live
// AmgVCycle by blocks with the same result as on a copy of K (read as CSR).
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "solvers/amg_vcycle.hpp"
#include "solvers/block_csr.hpp"
#include "solvers/sparse_solver.hpp"

namespace bpm {
namespace {

/// A symmetric, diagonally dominant matrix of `nodes` x `nodes` blocks of B x B: each node coupled
/// to a few random others. As the DSM's K, the off-diagonal 6 x 6 blocks store no zeros (the
/// entries (r, r + 3) and (r + 3, r) are pruned, as the zero diagonals of K's cross-product parts;
/// 3 x 3 blocks, translations only, are full), and one row keeps only its diagonal (a held
/// unknown): its block row is partly stored.
SparseMatrixRM block_matrix(int nodes, int B, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> other(0, nodes - 1);
  std::vector<Eigen::Triplet<double>> t;
  std::vector<double> row_sum(static_cast<std::size_t>(nodes * B), 0.0);
  const int held = 7 * B + 2;
  auto pruned = [&](int r, int c) {
    return (B == 6 && r % B == (c % B + 3) % B) || r == held || c == held;
  };
  for (int i = 0; i < nodes; ++i) {
    for (int n = 0; n < 4; ++n) {
      const int j = other(rng);
      if (j == i) continue;
      for (int r = 0; r < B; ++r) {
        for (int c = 0; c < B; ++c) {
          const int row = i * B + r, col = j * B + c;
          if (pruned(row, col) || pruned(col, row)) continue;
          const double v = u(rng);
          t.emplace_back(row, col, v);
          t.emplace_back(col, row, v);
          row_sum[static_cast<std::size_t>(row)] += std::abs(v);
          row_sum[static_cast<std::size_t>(col)] += std::abs(v);
        }
      }
    }
  }
  for (int i = 0; i < nodes * B; ++i)
    t.emplace_back(i, i, row_sum[static_cast<std::size_t>(i)] + 1.0);
  SparseMatrixRM K(nodes * B, nodes * B);
  K.setFromTriplets(t.begin(), t.end());  // sums the duplicates of a pair picked twice
  K.makeCompressed();
  return K;
}

Eigen::VectorXd random_vector(Eigen::Index n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) x[i] = u(rng);
  return x;
}

/// The CSR loop of amg_vcycle.cpp, with the values read as Value.
template <typename Value>
Eigen::VectorXd csr_product(const SparseMatrixRM& K, const Eigen::VectorXd& x) {
  Eigen::VectorXd y(K.rows());
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  const double* value = K.valuePtr();
  for (Eigen::Index i = 0; i < K.rows(); ++i) {
    double sum = 0.0;
    for (int k = outer[i]; k < outer[i + 1]; ++k)
      sum += static_cast<double>(static_cast<Value>(value[k])) * x[inner[k]];
    y[i] = sum;
  }
  return y;
}

BlockCsr<double> blocks_of(const SparseMatrixRM& K, int B) {
  return BlockCsr<double>::find(static_cast<int>(K.rows()), static_cast<int>(K.cols()),
                                K.outerIndexPtr(), K.innerIndexPtr(), K.valuePtr(), B);
}

void expect_identical(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  ASSERT_EQ(a.size(), b.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "row " << i;
}

class BlockProduct : public ::testing::TestWithParam<int> {};

TEST_P(BlockProduct, EqualsTheCsrLoopBitForBitInDoubleAndFloat) {
  const int B = GetParam();
  const SparseMatrixRM K = block_matrix(1000, B, 3);  // over kParallelRows rows: threaded
  const BlockCsr<double> blocks = blocks_of(K, B);
  ASSERT_FALSE(blocks.empty());
  const auto stored = static_cast<double>(blocks.blocks() * B * B);
  EXPECT_LT(stored, static_cast<double>(K.nonZeros()) * BlockCsr<double>::kMaxFill);
  EXPECT_GT(stored, static_cast<double>(K.nonZeros()));  // the pruned zeros are stored again
  const Eigen::VectorXd x = random_vector(K.rows(), 4);
  Eigen::VectorXd y(K.rows());
  blocks.multiply(x.data(), y.data());
  expect_identical(y, csr_product<double>(K, x));

  const BlockCsr<float> single = blocks.converted<float>();
  single.multiply(x.data(), y.data());
  expect_identical(y, csr_product<float>(K, x));

  Eigen::VectorXd sum = x;  // add: y += A x
  blocks.multiply(x.data(), sum.data(), /*add=*/true);
  expect_identical(sum, x + csr_product<double>(K, x));
}

TEST_P(BlockProduct, GivesTheSameResultForAnyThreadCount) {
  const int B = GetParam();
  const SparseMatrixRM K = block_matrix(1000, B, 5);
  const BlockCsr<double> blocks = blocks_of(K, B);
  const Eigen::VectorXd x = random_vector(K.rows(), 6);
  Eigen::VectorXd one(K.rows()), two(K.rows());
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  blocks.multiply(x.data(), one.data());
  omp_set_num_threads(2);
  blocks.multiply(x.data(), two.data());
  omp_set_num_threads(threads);
  expect_identical(one, two);
}

TEST_P(BlockProduct, RowsInHypresOrderGiveTheSameBlocks) {
  // AmgVCycle finds K's blocks while hypre holds it, each row's diagonal entry first.
  const int B = GetParam();
  SparseMatrixRM K = block_matrix(1000, B, 13);
  const BlockCsr<double> sorted = blocks_of(K, B);
  const int* outer = K.outerIndexPtr();
  int* columns = K.innerIndexPtr();
  double* values = K.valuePtr();
  int moved = 0;  // rows whose diagonal was not their first entry
  for (Eigen::Index r = 0; r < K.rows(); ++r) {
    const auto k =
        std::lower_bound(columns + outer[r], columns + outer[r + 1], r) - (columns + outer[r]);
    std::rotate(columns + outer[r], columns + outer[r] + k, columns + outer[r] + k + 1);
    std::rotate(values + outer[r], values + outer[r] + k, values + outer[r] + k + 1);
    moved += k > 0 ? 1 : 0;
  }
  ASSERT_GT(moved, K.rows() / 2);
  const BlockCsr<double> diagonal_first = blocks_of(K, B);
  ASSERT_EQ(diagonal_first.blocks(), sorted.blocks());
  const Eigen::VectorXd x = random_vector(K.rows(), 14);
  Eigen::VectorXd a(K.rows()), b(K.rows());
  sorted.multiply(x.data(), a.data());
  diagonal_first.multiply(x.data(), b.data());
  expect_identical(a, b);
}

INSTANTIATE_TEST_SUITE_P(BlockSizes, BlockProduct, ::testing::Values(3, 6));

TEST(BlockCsrTest, AMatrixThatIsNotBlockStructuredIsLeftToCsr) {
  // Scattered entries: a block would hold one or two of its 36.
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int> column(0, 599);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 600; ++i) {
    t.emplace_back(i, i, 4.0);
    for (int n = 0; n < 4; ++n) t.emplace_back(i, column(rng), -0.5);
  }
  SparseMatrixRM scattered(600, 600);
  scattered.setFromTriplets(t.begin(), t.end());
  EXPECT_TRUE(blocks_of(scattered, 6).empty());

  const SparseMatrixRM K = block_matrix(50, 6, 9);
  EXPECT_FALSE(blocks_of(K, 6).empty());
  EXPECT_TRUE(blocks_of(K, 1).empty());  // no blocks
  EXPECT_TRUE(blocks_of(K, 4).empty());  // only 3 and 6
  const SparseMatrixRM cut = K.topLeftCorner(K.rows() - 1, K.cols() - 1);
  EXPECT_TRUE(blocks_of(cut, 6).empty());  // rows not a multiple of 6
}

TEST(BlockCsrTest, ConjugateGradientsReadsTheCycleMatrixByBlocksWithTheSameResult) {
  SparseMatrixRM K = block_matrix(1000, 6, 10);
  AmgVCycle cycle(K, 6);
  ASSERT_NE(cycle.blocks(), nullptr);
  const Preconditioner M = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { cycle.apply(r, z); };
  const Eigen::VectorXd f = random_vector(K.rows(), 11);
  const Eigen::VectorXd shift = random_vector(K.rows(), 12).cwiseAbs();
  for (const Eigen::VectorXd* s : {static_cast<const Eigen::VectorXd*>(nullptr), &shift}) {
    Eigen::VectorXd by_blocks, by_rows;
    const int blocks_iterations =
        preconditioned_conjugate_gradients(K, M, f, by_blocks, 1e-10, 200, s, cycle.blocks());
    const int rows_iterations = preconditioned_conjugate_gradients(K, M, f, by_rows, 1e-10, 200, s);
    EXPECT_GT(blocks_iterations, 1);
    EXPECT_EQ(blocks_iterations, rows_iterations);
    expect_identical(by_blocks, by_rows);
    Eigen::VectorXd residual = f - K * by_blocks;
    if (s) residual -= s->cwiseProduct(by_blocks);
    EXPECT_LT(residual.norm(), 1e-8 * f.norm());
  }
}

}  // namespace
}  // namespace bpm
