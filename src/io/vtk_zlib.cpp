#include "io/vtk_zlib.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/parallel.hpp"

namespace bpm {
namespace {

static_assert(std::endian::native == std::endian::little, "the VTK files say LittleEndian");

void put_u64(std::string& out, std::size_t at, std::uint64_t v) {
  std::memcpy(out.data() + at, &v, sizeof v);
}

std::uint64_t get_u64(std::string_view in, std::size_t at) {
  if (at + 8 > in.size()) throw std::runtime_error("VTK zlib block: truncated header");
  std::uint64_t v = 0;
  std::memcpy(&v, in.data() + at, sizeof v);
  return v;
}

/// compress2 with a strategy: one zlib stream of `in` into `out`, resized to fit.
int deflate_block(std::string_view in, int level, int strategy, std::string& out) {
  z_stream z{};
  int rc = deflateInit2(&z, level, Z_DEFLATED, 15, 8, strategy);
  if (rc != Z_OK) return rc;
  out.resize(deflateBound(&z, static_cast<uLong>(in.size())));
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));  // zlib does not write it
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return rc == Z_STREAM_END ? Z_OK : rc;
}

}  // namespace

std::string vtk_zlib_block(std::string_view raw, int level, bool entropy_only) {
  const std::size_t blocks = (raw.size() + kVtkBlockSize - 1) / kVtkBlockSize;
  const int strategy = entropy_only ? Z_HUFFMAN_ONLY : Z_DEFAULT_STRATEGY;
  // The blocks are independent: compressed on the thread team (a frame of 1e5 particles has
  // ~2e3), each into its own buffer, then put one after the other.
  std::vector<std::string> packed(blocks);
  std::vector<int> rc(blocks, Z_OK);
  parallel_for(static_cast<std::int64_t>(blocks), blocks > 1, [&](std::int64_t k) {
    const auto b = static_cast<std::size_t>(k);
    const std::size_t begin = b * kVtkBlockSize;
    rc[b] = deflate_block(raw.substr(begin, kVtkBlockSize), level, strategy, packed[b]);
  });
  std::string out(8 * (3 + blocks), '\0');
  put_u64(out, 0, blocks);
  put_u64(out, 8, kVtkBlockSize);
  put_u64(out, 16, raw.size() % kVtkBlockSize);
  for (std::size_t b = 0; b < blocks; ++b) {
    // Only Z_MEM_ERROR is possible with a deflateBound-sized buffer and a valid level.
    if (rc[b] != Z_OK) throw std::runtime_error("zlib deflate failed: " + std::to_string(rc[b]));
    put_u64(out, 8 * (3 + b), packed[b].size());
  }
  for (const std::string& block : packed) out += block;
  return out;
}

std::string vtk_zlib_unblock(std::string_view block, std::size_t* used) {
  const std::uint64_t blocks = get_u64(block, 0), size = get_u64(block, 8),
                      last = get_u64(block, 16);
  if (blocks > block.size() / 8) throw std::runtime_error("VTK zlib block: bad block count");
  std::size_t at = 8 * (3 + blocks);
  if (at > block.size()) throw std::runtime_error("VTK zlib block: truncated header");
  std::string raw;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t packed = get_u64(block, 8 * (3 + b));
    if (packed > block.size() - at) throw std::runtime_error("VTK zlib block: truncated data");
    uLongf expect = static_cast<uLongf>(b + 1 == blocks && last != 0 ? last : size);
    const std::size_t begin = raw.size();
    raw.resize(begin + expect);
    const int rc =
        uncompress(reinterpret_cast<Bytef*>(raw.data() + begin), &expect,
                   reinterpret_cast<const Bytef*>(block.data() + at), static_cast<uLong>(packed));
    if (rc != Z_OK || begin + expect != raw.size())
      throw std::runtime_error("VTK zlib block: block " + std::to_string(b) + " does not inflate");
    at += packed;
  }
  if (used != nullptr) *used = at;
  return raw;
}

}  // namespace bpm
