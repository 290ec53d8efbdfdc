#pragma once
/// A fixed binary layout for checkpoints (scenario/checkpoint.hpp): integers little-endian whatever
/// the machine, doubles as their raw IEEE 754 bits (so they come back bit for bit), vectors as a
/// 64-bit count then their elements. The reader checks every length against what is left and
/// throws std::out_of_range on a short or corrupt buffer; the caller turns that into its error.
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/quaternion.hpp"
#include "core/vec3.hpp"

namespace bpm {

/// FNV-1a, 64 bit: the checksum of a checkpoint's payload and the hash of a scenario's identity.
inline std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = 14695981039346656037ull) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

class ByteWriter {
 public:
  void u8(std::uint8_t v) { bytes_ += static_cast<char>(v); }
  void u32(std::uint32_t v) { unsigned_bytes(v, 4); }
  void u64(std::uint64_t v) { unsigned_bytes(v, 8); }
  void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void vec3(const Vec3& v) {
    f64(v.x);
    f64(v.y);
    f64(v.z);
  }
  void quat(const Quat& q) {
    f64(q.w);
    f64(q.x);
    f64(q.y);
    f64(q.z);
  }
  void text(std::string_view s) {
    u64(s.size());
    bytes_ += s;
  }
  /// A count, then each element written by `put(writer, element)`.
  template <class T, class Put>
  void list(const std::vector<T>& v, Put put) {
    u64(v.size());
    for (const T& e : v) put(*this, e);
  }

  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  void unsigned_bytes(std::uint64_t v, int n) {
    // Byte by byte into a buffer, then one append: the compiler turns this into a single store.
    char b[8];
    for (int k = 0; k < n; ++k) b[k] = static_cast<char>((v >> (8 * k)) & 0xffu);
    bytes_.append(b, static_cast<std::size_t>(n));
  }
  std::string bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}

  std::uint8_t u8() { return static_cast<std::uint8_t>(take(1)[0]); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_bytes(4)); }
  std::uint64_t u64() { return unsigned_bytes(8); }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() { return std::bit_cast<double>(u64()); }
  Vec3 vec3() {
    Vec3 v;
    v.x = f64();
    v.y = f64();
    v.z = f64();
    return v;
  }
  Quat quat() {
    Quat q;
    q.w = f64();
    q.x = f64();
    q.y = f64();
    q.z = f64();
    return q;
  }
  std::string text() { return std::string(take(count(1))); }
  /// A list written by ByteWriter::list; each element read by `get(reader)`. `min_bytes` is the
  /// smallest size of one element, so a corrupt count fails before any allocation.
  template <class T, class Get>
  std::vector<T> list(std::size_t min_bytes, Get get) {
    const std::size_t n = count(min_bytes);
    std::vector<T> v;
    v.reserve(n);
    for (std::size_t i = 0; i < n; ++i) v.push_back(get(*this));
    return v;
  }

  std::size_t left() const { return bytes_.size() - at_; }
  /// The next n bytes as they are (for a column of fixed-size values read in one copy).
  std::string_view raw(std::size_t n) { return take(n); }

 private:
  std::size_t count(std::size_t min_bytes) {
    const std::uint64_t n = u64();
    if (min_bytes > 0 && n > left() / min_bytes)
      throw std::out_of_range("a count beyond the end of the data");
    return static_cast<std::size_t>(n);
  }
  std::string_view take(std::size_t n) {
    if (n > left()) throw std::out_of_range("the data ends early");
    const std::string_view s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  std::uint64_t unsigned_bytes(int n) {
    const std::string_view s = take(static_cast<std::size_t>(n));
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k)
      v |= static_cast<std::uint64_t>(static_cast<unsigned char>(s[k])) << (8 * k);
    return v;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace bpm
