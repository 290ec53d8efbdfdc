#include "io/csv_table.hpp"

#include <fmt/core.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "core/error.hpp"
#include "io/parse_number.hpp"

namespace bpm {
namespace {

/// The whole file, in blocks. A file that never ends (`/dev/zero`) or has no line ends is read only
/// until its current line passes the limit; the line scan then reports that line. A regular file's
/// blocks are about its size (at least 64 KiB, for files whose size is not what they hold, as in
/// /proc): each block is zeroed by the resize first, and 16 MiB zeroed for a 200-byte file cost
/// ~20 ms a read.
std::string read_bytes(std::FILE* file, const std::string& path) {
  std::size_t block = std::size_t{16} << 20;
  std::string bytes;
  struct stat info {};
  if (::fstat(::fileno(file), &info) == 0 && S_ISREG(info.st_mode)) {
    block = std::clamp(static_cast<std::size_t>(info.st_size) + 1, std::size_t{64} << 10, block);
    bytes.reserve(static_cast<std::size_t>(info.st_size) + block);
  }
  std::size_t line_start = 0;
  while (true) {
    const std::size_t old = bytes.size();
    bytes.resize(old + block);
    const std::size_t got = std::fread(bytes.data() + old, 1, block, file);
    bytes.resize(old + got);
    if (got == 0) break;
    if (const void* nl = ::memrchr(bytes.data() + old, '\n', got)) {
      line_start = static_cast<std::size_t>(static_cast<const char*>(nl) - bytes.data()) + 1;
    }
    if (bytes.size() - line_start > kMaxCsvLineBytes) break;
  }
  if (std::ferror(file)) {
    throw InputError(path, "the file cannot be read", "check that it is a readable file");
  }
  return bytes;
}

/// The first data row's content and line, to tell a header from data; empty if there is none.
std::pair<std::string_view, std::int64_t> first_data_row(const std::string& bytes) {
  std::int64_t line = 1;
  for (std::size_t pos = 0; pos < bytes.size(); ++line) {
    const std::size_t nl = bytes.find('\n', pos);
    const std::size_t stop = nl == std::string::npos ? bytes.size() : nl;
    const std::string_view content = csv_content({bytes.data() + pos, stop - pos}, line);
    if (is_csv_data(content)) return {content, line};
    pos = stop + 1;
  }
  return {};
}

}  // namespace

std::string CsvTable::where(const CsvRow& row) const {
  return fmt::format("{}:{}", path, row.line);
}

std::string CsvTable::where(std::size_t k) const {
  return fmt::format("{}:{}", path, line(k));
}

double CsvTable::number(const CsvRow& row, std::size_t column, std::string_view column_name) const {
  const auto v = parse_double(row.fields[column]);
  if (!v) {
    throw InputError(where(row),
                     fmt::format("column {} ('{}') is '{}', not a finite number", column + 1,
                                 column_name, row.fields[column]),
                     "write a number such as 0.4 or 2e-3");
  }
  return *v;
}

std::int64_t CsvTable::integer(const CsvRow& row, std::size_t column,
                               std::string_view column_name) const {
  const auto v = parse_int64(row.fields[column]);
  if (!v) {
    throw InputError(where(row),
                     fmt::format("column {} ('{}') is '{}', not an integer", column + 1,
                                 column_name, row.fields[column]),
                     "particle ids are whole numbers");
  }
  return *v;
}

CsvRowError CsvTable::convert_rows(const std::function<void(std::size_t, const CsvRow&)>& convert) {
  const std::size_t skip = header.empty() ? 0 : 1;  // the header is the file's data row 0
  row_line_.assign(size(), 0);
  std::vector<CsvRowError> errors(text_.chunks.size());
  const auto n_chunks = static_cast<std::int64_t>(text_.chunks.size());
#pragma omp parallel
  {
    std::vector<std::string_view> fields;
#pragma omp for schedule(dynamic)
    for (std::int64_t c = 0; c < n_chunks; ++c) {
      CsvRowError& error = errors[static_cast<std::size_t>(c)];
      try {
        for_each_csv_row(text_, text_.chunks[static_cast<std::size_t>(c)],
                         [&](std::size_t row, std::int64_t line, std::string_view content) {
                           if (row < skip) return;
                           error.row = row - skip;  // should convert throw
                           row_line_[error.row] = static_cast<int>(line);
                           split_csv_fields(content, fields);
                           convert(error.row, CsvRow{static_cast<int>(line), fields});
                         });
        error.row = CsvRowError{}.row;
      } catch (...) {
        error.error = std::current_exception();
      }
    }
  }
  CsvRowError first;
  for (const CsvRowError& e : errors) {
    if (e.error && e.row < first.row) first = e;
  }
  return first;
}

CsvTable read_csv(const std::string& path, const std::string& referenced_from) {
  // A folder opens as an empty stream on Linux: it would read as a file without rows.
  if (std::filesystem::is_directory(path)) {
    throw InputError(referenced_from, "'" + path + "' is a folder, not a CSV file",
                     "name the CSV file inside it");
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) {
    throw InputError(referenced_from, "cannot open CSV file '" + path + "'",
                     "paths are relative to the scenario file's folder");
  }
  CsvTable table;
  table.path = path;
  table.text_ = index_csv_text(read_bytes(file.get(), path), kMaxCsvLineBytes);
  const CsvText& text = table.text_;
  if (text.too_long_line != 0) {
    throw InputError(
        fmt::format("{}:{}", path, text.too_long_line),
        fmt::format("the line is longer than the limit of {} bytes (1 MiB) for a CSV line",
                    kMaxCsvLineBytes),
        "is this a CSV file? rows are short, e.g. '0,0.1,0.2,0.3,0.05'");
  }
  if (text.lines > kMaxCsvLines) {
    throw InputError(
        fmt::format("{}:{}", path, std::int64_t{kMaxCsvLines} + 1),
        fmt::format("the file has more than the limit of {} lines for a CSV file", kMaxCsvLines),
        "is this the right file? ids and line numbers are 32-bit");
  }
  const auto [content, line] = first_data_row(text.bytes);
  std::vector<std::string_view> fields;
  split_csv_fields(content, fields);
  if (!content.empty() && !parse_double(fields.front())) {
    table.header.assign(fields.begin(), fields.end());
    table.header_line = static_cast<int>(line);
  }
  return table;
}

}  // namespace bpm
