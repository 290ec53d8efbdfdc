#include "io/csv_chunks.hpp"

#include <algorithm>

namespace bpm {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

/// About 4 MiB a chunk: enough chunks to balance the threads, few enough that their bookkeeping
/// costs nothing. The cut does not change any result, only which thread parses a row.
constexpr std::size_t kChunkBytes = std::size_t{4} << 20;

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

/// Chunk boundaries: about every kChunkBytes, moved on to the next line start.
std::vector<CsvChunk> cut(const std::string& bytes) {
  std::vector<CsvChunk> chunks;
  std::size_t begin = 0;
  while (begin < bytes.size()) {
    std::size_t end = std::min(bytes.size(), begin + kChunkBytes);
    if (end < bytes.size()) {
      const std::size_t nl = bytes.find('\n', end - 1);
      end = nl == std::string::npos ? bytes.size() : nl + 1;
    }
    chunks.push_back({begin, end});
    begin = end;
  }
  return chunks;
}

}  // namespace

std::string_view csv_content(std::string_view line, std::int64_t line_number) {
  if (line_number == 1 && line.starts_with(kUtf8Bom)) line.remove_prefix(kUtf8Bom.size());
  return trim(line);
}

void split_csv_fields(std::string_view content, std::vector<std::string_view>& fields) {
  fields.clear();
  while (true) {
    const auto comma = content.find(',');
    fields.push_back(trim(content.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    content.remove_prefix(comma + 1);
  }
}

CsvText index_csv_text(std::string bytes, std::size_t max_line_bytes) {
  CsvText text;
  text.bytes = std::move(bytes);
  text.chunks = cut(text.bytes);
  const auto n_chunks = static_cast<std::int64_t>(text.chunks.size());
  // Per chunk: its lines (into first_line for now) and the first too-long one (chunk-local).
  std::vector<std::int64_t> too_long(text.chunks.size(), 0);
  const char* const data = text.bytes.data();
#pragma omp parallel for schedule(dynamic)
  for (std::int64_t c = 0; c < n_chunks; ++c) {
    CsvChunk& chunk = text.chunks[static_cast<std::size_t>(c)];
    std::int64_t lines = 0;
    for (std::size_t pos = chunk.begin; pos < chunk.end;) {
      const void* nl = std::memchr(data + pos, '\n', chunk.end - pos);
      const std::size_t stop =
          nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - data) : chunk.end;
      ++lines;
      if (stop - pos > max_line_bytes && too_long[static_cast<std::size_t>(c)] == 0) {
        too_long[static_cast<std::size_t>(c)] = lines;
      }
      // Only line 1, at byte 0, may start with a byte-order mark; any other number will do here.
      if (is_csv_data(csv_content({data + pos, stop - pos}, pos == 0 ? 1 : 2))) {
        ++chunk.rows;
      }
      pos = stop + 1;
    }
    chunk.first_line = lines;
  }
  // Running sums, in chunk order: each chunk's first line and row.
  for (std::size_t c = 0; c < text.chunks.size(); ++c) {
    CsvChunk& chunk = text.chunks[c];
    const std::int64_t lines = chunk.first_line;
    if (text.too_long_line == 0 && too_long[c] != 0) text.too_long_line = text.lines + too_long[c];
    chunk.first_line = text.lines + 1;
    chunk.first_row = text.rows;
    text.lines += lines;
    text.rows += chunk.rows;
  }
  return text;
}

}  // namespace bpm
