#pragma once
/// The particle pairs bonded so far, to refuse a duplicate bond (i-j and j-i are one pair). A flat
/// open-addressing hash set of 64-bit keys: a std::set of 8e6 pairs took 10 s of the 8e6-bond box's
/// load (a node allocation and a tree walk each), this takes well under one.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace bpm {

class BondPairSet {
 public:
  /// Room for `expected` pairs without growing.
  explicit BondPairSet(std::size_t expected = 0) { rehash(std::bit_ceil(2 * expected + 16)); }

  /// Adds the pair {a, b} (non-negative indices); false if it was there already.
  bool insert(std::int32_t a, std::int32_t b) {
    if (2 * (size_ + 1) > slots_.size()) rehash(2 * slots_.size());
    if (!place(key(a, b))) return false;
    ++size_;
    return true;
  }

  /// Asks the cache for the pair's slot, a few inserts ahead of inserting it.
  void prefetch(std::int32_t a, std::int32_t b) const {
    __builtin_prefetch(&slots_[home(key(a, b))]);
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // no pair of int32 indices has it

  static std::uint64_t key(std::int32_t a, std::int32_t b) {
    return (std::uint64_t{std::uint32_t(std::min(a, b))} << 32) | std::uint32_t(std::max(a, b));
  }
  /// The key's first slot: its Fibonacci hash.
  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  /// Linear probing from the key's Fibonacci hash; false if the key is there.
  bool place(std::uint64_t key) {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t s = home(key);; s = (s + 1) & mask) {
      if (slots_[s] == key) return false;
      if (slots_[s] == kEmpty) {
        slots_[s] = key;
        return true;
      }
    }
  }

  void rehash(std::size_t capacity) {
    std::vector<std::uint64_t> old(capacity, kEmpty);
    old.swap(slots_);
    shift_ = 64 - std::countr_zero(capacity);
    for (const std::uint64_t key : old) {
      if (key != kEmpty) place(key);
    }
  }

  std::vector<std::uint64_t> slots_;
  int shift_ = 64;
  std::size_t size_ = 0;
};

}  // namespace bpm
