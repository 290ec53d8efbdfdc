#pragma once
/// The compressed data block of VTK's XML formats (vtkZLibDataCompressor, header_type UInt64):
/// a header of UInt64 [number of blocks, block size, size of the last block (0 if it is full),
/// compressed size of each block], then the zlib streams of the blocks one after the other. The
/// raw data is cut into blocks of kVtkBlockSize bytes (VTK's default), each compressed alone.
#include <cstddef>
#include <string>
#include <string_view>

namespace bpm {

inline constexpr std::size_t kVtkBlockSize = 32768;

/// The block of `raw` at zlib `level` (1 fastest .. 9 smallest). `entropy_only` (Huffman coding
/// without string matching, Z_HUFFMAN_ONLY) suits doubles with full mantissas: no larger, and
/// about twice as fast as level 1 (BENCHMARKS.md, "VTK frames"); integers compress better with
/// matching. The blocks are compressed on the OpenMP thread team.
std::string vtk_zlib_block(std::string_view raw, int level, bool entropy_only = false);

/// The raw data of the block at the start of `block` (the reader's side: tests and tools);
/// `used` (if given) gets the block's length in bytes. Throws std::runtime_error when it is
/// truncated or not zlib data.
std::string vtk_zlib_unblock(std::string_view block, std::size_t* used = nullptr);

}  // namespace bpm
