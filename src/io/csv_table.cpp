#include "io/csv_table.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>

#include "core/error.hpp"
#include "io/parse_number.hpp"

namespace bpm {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

/// std::getline without a bound reads `/dev/zero` (or a binary file without newlines) into one
/// endless line. Reads up to '\n'; false at the end of the stream, or when the line (without its
/// '\n') would exceed kMaxCsvLineBytes, with `text` holding that much.
bool read_line(std::istream& in, std::string& text, bool& too_long) {
  text.clear();
  too_long = false;
  std::streambuf& buffer = *in.rdbuf();
  for (int c; (c = buffer.sbumpc()) != std::char_traits<char>::eof();) {
    if (c == '\n') return true;
    if (text.size() == kMaxCsvLineBytes) {
      too_long = true;
      return false;
    }
    text.push_back(static_cast<char>(c));
  }
  return !text.empty();
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> fields;
  while (true) {
    const auto comma = line.find(',');
    fields.emplace_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return fields;
}

}  // namespace

std::string CsvTable::where(const CsvRow& row) const { return fmt::format("{}:{}", path, row.line); }

double CsvTable::number(const CsvRow& row, std::size_t column, std::string_view column_name) const {
  const auto v = parse_double(row.fields.at(column));
  if (!v) {
    throw InputError(where(row), fmt::format("column {} ('{}') is '{}', not a finite number", column + 1, column_name,
                                             row.fields[column]),
                     "write a number such as 0.4 or 2e-3");
  }
  return *v;
}

std::int64_t CsvTable::integer(const CsvRow& row, std::size_t column, std::string_view column_name) const {
  const auto v = parse_int64(row.fields.at(column));
  if (!v) {
    throw InputError(where(row), fmt::format("column {} ('{}') is '{}', not an integer", column + 1, column_name,
                                             row.fields[column]),
                     "particle ids are whole numbers");
  }
  return *v;
}

CsvTable read_csv(const std::string& path, const std::string& referenced_from) {
  // A folder opens as an empty stream on Linux: it would read as a file without rows.
  if (std::filesystem::is_directory(path)) {
    throw InputError(referenced_from, "'" + path + "' is a folder, not a CSV file",
                     "name the CSV file inside it");
  }
  std::ifstream in(path);
  if (!in) {
    throw InputError(referenced_from, "cannot open CSV file '" + path + "'",
                     "paths are relative to the scenario file's folder");
  }
  CsvTable table;
  table.path = path;
  std::string text;
  int line = 0;
  bool first = true;
  for (bool too_long = false; read_line(in, text, too_long) || too_long;) {
    if (too_long) {
      throw InputError(fmt::format("{}:{}", path, line + 1),
                       fmt::format("the line is longer than the limit of {} bytes (1 MiB) for a CSV line",
                                   kMaxCsvLineBytes),
                       "is this a CSV file? rows are short, e.g. '0,0.1,0.2,0.3,0.05'");
    }
    if (line == kMaxCsvLines) {
      throw InputError(fmt::format("{}:{}", path, line + 1),
                       fmt::format("the file has more than the limit of {} lines for a CSV file", kMaxCsvLines),
                       "is this the right file? ids and line numbers are 32-bit");
    }
    ++line;
    // Spreadsheets save "CSV UTF-8" with a byte-order mark in front of the header.
    if (line == 1 && text.starts_with(kUtf8Bom)) text.erase(0, kUtf8Bom.size());
    const std::string_view content = trim(text);
    if (content.empty() || content.front() == '#') continue;
    std::vector<std::string> fields = split(content);
    if (first && !parse_double(fields.front())) {
      table.header = std::move(fields);
      table.header_line = line;
    } else {
      table.rows.push_back({line, std::move(fields)});
    }
    first = false;
  }
  return table;
}

}  // namespace bpm
