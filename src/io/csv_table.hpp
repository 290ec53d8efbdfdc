#pragma once
/// A minimal CSV reader for scenario inputs (particles.csv, bonds.csv): comma separated, no
/// quoting, fields trimmed, blank lines and lines starting with '#' skipped, a UTF-8 byte-order
/// mark at the start ignored. The first data line is taken as a header when its first field is not
/// a number. Every value read names the file and the line, so an error points at the offending row.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace bpm {

/// Size limits: a longer line (without its newline) or more lines is an InputError naming the limit,
/// never an endless read (`file: /dev/zero`) or an overflowed line number.
constexpr std::size_t kMaxCsvLineBytes = std::size_t{1} << 20;
constexpr int kMaxCsvLines = std::numeric_limits<int>::max();

struct CsvRow {
  int line = 0;  ///< 1-based line number in the file
  std::vector<std::string> fields;
};

struct CsvTable {
  std::string path;
  std::vector<std::string> header;  ///< empty if the file has no header line
  int header_line = 0;              ///< 1-based line of the header, 0 if none
  std::vector<CsvRow> rows;

  /// "PATH:LINE", for messages about one row.
  std::string where(const CsvRow& row) const;
  /// The field as a finite number / integer; otherwise an InputError naming file, line and column.
  double number(const CsvRow& row, std::size_t column, std::string_view column_name) const;
  std::int64_t integer(const CsvRow& row, std::size_t column, std::string_view column_name) const;
};

/// Reads the whole file; `referenced_from` (e.g. "scenario.yaml:7: particles.file") is named if the
/// file cannot be opened.
CsvTable read_csv(const std::string& path, const std::string& referenced_from);

}  // namespace bpm
