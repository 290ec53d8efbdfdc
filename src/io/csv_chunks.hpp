#pragma once
/// The text of a CSV file cut into chunks at line ends, for parsing in parallel (csv_table.hpp).
/// One counting pass, in parallel, gives each chunk the number of its first line and of its first
/// data row; any chunk can then be parsed on its own and its rows put in their place, which keeps
/// the line numbers in messages right across chunk boundaries and the result independent of the
/// thread count.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace bpm {

struct CsvChunk {
  std::size_t begin = 0, end = 0;  ///< bytes [begin, end): whole lines, the last '\n' included
  std::int64_t first_line = 1;     ///< 1-based number of its first line
  std::size_t first_row = 0;       ///< file-wide index of its first data row
  std::size_t rows = 0;            ///< its data rows
};

struct CsvText {
  std::string bytes;
  std::vector<CsvChunk> chunks;
  std::size_t rows = 0;            ///< data rows in the file (a header line counts as one here)
  std::int64_t lines = 0;          ///< lines in the file
  std::int64_t too_long_line = 0;  ///< first line longer than the limit; 0 if none
};

/// Cuts `bytes` into chunks and counts their lines and data rows (in parallel).
CsvText index_csv_text(std::string bytes, std::size_t max_line_bytes);

/// The line's content: without a UTF-8 byte-order mark on line 1 (spreadsheets save "CSV UTF-8"
/// with one) and trimmed of spaces, tabs and the '\r' of a CRLF line end. A data row is a content
/// neither empty nor a '#' comment.
std::string_view csv_content(std::string_view line, std::int64_t line_number);
inline bool is_csv_data(std::string_view content) {
  return !content.empty() && content.front() != '#';
}

/// The content's comma-separated fields, each trimmed, into `fields` (reused: no allocation per
/// row once it has grown).
void split_csv_fields(std::string_view content, std::vector<std::string_view>& fields);

/// Calls visit(row, line_number, content) for each data row of the chunk, in order.
template <class Visit>
void for_each_csv_row(const CsvText& text, const CsvChunk& chunk, Visit&& visit) {
  const char* const data = text.bytes.data();
  std::size_t row = chunk.first_row;
  std::int64_t line = chunk.first_line;
  for (std::size_t pos = chunk.begin; pos < chunk.end; ++line) {
    const void* nl = std::memchr(data + pos, '\n', chunk.end - pos);
    const std::size_t stop =
        nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - data) : chunk.end;
    const std::string_view content = csv_content({data + pos, stop - pos}, line);
    if (is_csv_data(content)) visit(row++, line, content);
    pos = stop + 1;
  }
}

}  // namespace bpm
