#include "solvers/block_csr.hpp"

#include <algorithm>
#include <cstddef>

namespace bpm {
namespace {

/// The first columns of the blocks of the B rows from `row`: the distinct column / B of their
/// entries, sorted (into `out`, reused between block rows).
void block_columns(const int* outer, const int* inner, int row, int B, std::vector<int>& out) {
  out.clear();
  for (int i = row; i < row + B; ++i) {
    for (int k = outer[i]; k < outer[i + 1]; ++k) {
      const int first = inner[k] - inner[k] % B;
      if (out.empty() || out.back() != first) out.push_back(first);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace

template <typename Value>
BlockCsr<Value> BlockCsr<Value>::find(int rows, int cols, const int* outer, const int* inner,
                                      const double* values, int block_size) {
  const int B = block_size;
  BlockCsr m;
  if ((B != 3 && B != 6) || rows <= 0 || rows % B != 0 || cols % B != 0) return m;
  const int count = rows / B;
  m.first_.assign(static_cast<std::size_t>(count) + 1, 0);
  std::vector<int> columns;
#pragma omp parallel for schedule(static) firstprivate(columns) if (rows > kParallelRows)
  for (int b = 0; b < count; ++b) {
    block_columns(outer, inner, b * B, B, columns);
    m.first_[b + 1] = static_cast<int>(columns.size());
  }
  for (int b = 0; b < count; ++b) m.first_[b + 1] += m.first_[b];
  const auto blocks = static_cast<std::size_t>(m.first_[count]);
  if (static_cast<double>(blocks) * B * B > kMaxFill * outer[rows]) return {};  // not blocks

  m.columns_.resize(blocks);
  m.values_.resize(blocks * static_cast<std::size_t>(B * B));  // zeros where K stores none
#pragma omp parallel for schedule(static) firstprivate(columns) if (rows > kParallelRows)
  for (int b = 0; b < count; ++b) {
    block_columns(outer, inner, b * B, B, columns);
    std::copy(columns.begin(), columns.end(), m.columns_.begin() + m.first_[b]);
    const auto begin = m.columns_.begin() + m.first_[b], end = m.columns_.begin() + m.first_[b + 1];
    for (int r = 0; r < B; ++r) {
      for (int k = outer[b * B + r]; k < outer[b * B + r + 1]; ++k) {
        const int q = inner[k] % B;
        const auto j = static_cast<std::size_t>(std::lower_bound(begin, end, inner[k] - q) -
                                                m.columns_.begin());
        m.values_[j * B * B + q * B + r] = static_cast<Value>(values[k]);
      }
    }
  }
  m.block_size_ = B;
  m.rows_ = rows;
  return m;
}

template <typename Value>
template <typename Other>
BlockCsr<Other> BlockCsr<Value>::converted() const {
  BlockCsr<Other> m;
  m.block_size_ = block_size_;
  m.rows_ = rows_;
  m.first_ = first_;
  m.columns_ = columns_;
  m.values_.resize(values_.size());
  const auto n = static_cast<std::ptrdiff_t>(values_.size());
#pragma omp parallel for schedule(static) if (rows_ > kParallelRows)
  for (std::ptrdiff_t k = 0; k < n; ++k) m.values_[k] = static_cast<Other>(values_[k]);
  return m;
}

/// The B rows of a block row are B independent sums, side by side (in SIMD lanes): each is summed
/// in its CSR order, and they overlap instead of waiting on one another.
template <typename Value>
template <int B>
void BlockCsr<Value>::product(const double* x, double* y, bool add) const {
  const int count = rows_ / B;
#pragma omp parallel for schedule(static) if (rows_ > kParallelRows)
  for (int b = 0; b < count; ++b) {
    double sum[B] = {};
    for (int j = first_[b]; j < first_[b + 1]; ++j) {
      const Value* v = values_.data() + static_cast<std::size_t>(j) * B * B;
      const double* xj = x + columns_[j];
      for (int q = 0; q < B; ++q) {
        for (int r = 0; r < B; ++r) sum[r] += static_cast<double>(v[q * B + r]) * xj[q];
      }
    }
    double* yb = y + b * B;
    for (int r = 0; r < B; ++r) yb[r] = add ? yb[r] + sum[r] : sum[r];
  }
}

template <typename Value>
void BlockCsr<Value>::multiply(const double* x, double* y, bool add) const {
  if (block_size_ == 6) return product<6>(x, y, add);
  product<3>(x, y, add);
}

template class BlockCsr<double>;
template class BlockCsr<float>;
template BlockCsr<float> BlockCsr<double>::converted<float>() const;

}  // namespace bpm
