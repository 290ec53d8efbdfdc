#pragma once
/// A minimal CSV reader for scenario inputs (particles.csv, bonds.csv): comma separated, no
/// quoting, fields trimmed, LF or CRLF line ends, blank lines and lines starting with '#' skipped,
/// a UTF-8 byte-order mark at the start ignored. The first data line is taken as a header when its
/// first field is not a number. Every value read names the file and the line, so an error points at
/// the offending row.
///
/// Structure files run to millions of rows (the 8e6-bond box: 334 MB), so the file is read in one
/// go and its rows are handed to the caller from several threads (csv_chunks.hpp): the caller
/// converts row k into slot k of its own columns, and the result does not depend on the thread
/// count. A row that fails is reported at its place in the file order (CsvRowError), so the first
/// error in the file is the one the user sees, as with a sequential read.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/csv_chunks.hpp"

namespace bpm {

/// Size limits: a longer line (without its newline) or more lines is an InputError naming the
/// limit, never an endless read (`file: /dev/zero`) or an overflowed line number.
constexpr std::size_t kMaxCsvLineBytes = std::size_t{1} << 20;
constexpr int kMaxCsvLines = std::numeric_limits<int>::max();

struct CsvRow {
  int line = 0;                              ///< 1-based line number in the file
  std::span<const std::string_view> fields;  ///< trimmed; they view the table's text
};

/// The first data row (in file order) whose conversion threw, with what it threw. Every row before
/// it was converted.
struct CsvRowError {
  std::size_t row = std::numeric_limits<std::size_t>::max();
  std::exception_ptr error;
  /// Rethrows the error at its row: call it for each row, in order, before using the row, so that
  /// checks made in order (duplicate ids, say) on earlier rows still come first.
  void rethrow_at(std::size_t k) const {
    if (k == row) std::rethrow_exception(error);
  }
};

class CsvTable {
 public:
  std::string path;
  std::vector<std::string> header;  ///< empty if the file has no header line
  int header_line = 0;              ///< 1-based line of the header, 0 if none

  /// The number of data rows (after the header, without blank and comment lines).
  std::size_t size() const { return text_.rows - (header.empty() ? 0 : 1); }

  /// Calls convert(k, row) for each data row k (0-based, file order) from several threads at once:
  /// convert must only write what belongs to row k. Stops a chunk at its first exception; the first
  /// in file order is returned. Also records each row's line for line() and where().
  CsvRowError convert_rows(const std::function<void(std::size_t, const CsvRow&)>& convert);

  /// The line of data row k (after convert_rows).
  int line(std::size_t k) const { return row_line_[k]; }
  /// "PATH:LINE", for messages about one row.
  std::string where(const CsvRow& row) const;
  std::string where(std::size_t k) const;
  /// The field as a finite number / integer; otherwise an InputError naming file, line and column.
  double number(const CsvRow& row, std::size_t column, std::string_view column_name) const;
  std::int64_t integer(const CsvRow& row, std::size_t column, std::string_view column_name) const;

 private:
  friend CsvTable read_csv(const std::string& path, const std::string& referenced_from);
  CsvText text_;
  std::vector<int> row_line_;
};

/// Reads the whole file and finds its header and rows; `referenced_from` (e.g. "scenario.yaml:7:
/// particles.file") is named if the file cannot be opened.
CsvTable read_csv(const std::string& path, const std::string& referenced_from);

}  // namespace bpm
