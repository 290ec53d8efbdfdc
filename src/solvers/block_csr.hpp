#pragma once
/// A copy of a compressed row-major matrix in dense B x B blocks (block sparse rows; B = 3 or 6,
/// the unknowns of one particle: a bonded or touching pair couples all of them), for products
/// bound by memory bandwidth: CSR streams a 4-byte column index with every value, blocks one per
/// B^2 values. The assembly prunes exact zeros (the zero diagonals of the cross-product parts), so
/// the blocks store them again: on the 1e5-particle cylinder K's 30.4 M entries make 908,551
/// blocks of 36 (7.1 % zeros); a product streams 4.5 instead of 8 bytes an entry with float values
/// and 8.8 instead of 12 with double. On one thread (about 7 GB/s), a matrix like it took 12-14
/// instead of 24 ms (float) and 22 instead of 30-32 ms (double).
///
/// Each row is summed in the CSR loop's order (blocks by increasing column, the columns of a block
/// in order). A stored zero adds 0 * x = +-0 to a sum that is never -0 (it starts at +0), which
/// changes nothing, so for finite x the products equal the CSR loop's bit for bit, for any number
/// of threads.
#include <cstdint>
#include <vector>

namespace bpm {

/// Below this many rows a product runs on one thread (thread start-up would cost more than the
/// work).
constexpr int kParallelRows = 4096;

template <typename Value>
class BlockCsr {
 public:
  BlockCsr() = default;

  /// The blocks of the rows x cols matrix (outer, inner, values: compressed; a row's columns in
  /// any order, so hypre's, with the diagonal first, will do). Empty (use CSR) unless block_size
  /// is 3 or 6, rows and cols are multiples of it, and the blocks hold at most kMaxFill times the
  /// stored entries (K is block-structured).
  static BlockCsr find(int rows, int cols, const int* outer, const int* inner, const double* values,
                       int block_size);
  /// The stored entries (zeros included) may be at most this many times the matrix's: beyond, the
  /// zeros would cost more traffic than the indices save.
  static constexpr double kMaxFill = 1.4;

  /// The same blocks with the values converted (the V-cycle's float copy of K).
  template <typename Other>
  BlockCsr<Other> converted() const;

  bool empty() const { return block_size_ == 0; }
  int rows() const { return rows_; }
  std::int64_t blocks() const { return static_cast<std::int64_t>(columns_.size()); }

  /// y = A x (add: y += A x). The same result as the CSR loop, bit for bit, for finite x.
  void multiply(const double* x, double* y, bool add = false) const;

 private:
  template <typename>
  friend class BlockCsr;
  template <int B>
  void product(const double* x, double* y, bool add) const;

  int block_size_ = 0, rows_ = 0;
  std::vector<int> first_;     ///< block row b's blocks: [first_[b], first_[b + 1])
  std::vector<int> columns_;   ///< each block's first column
  std::vector<Value> values_;  ///< B x B a block, column by column (the B rows of a column
                               ///< side by side: one x value multiplies them all)
};

}  // namespace bpm
