// The chunked, parallel CSV reader (io/csv_table.hpp, io/csv_chunks.hpp): rows in file order and
// line numbers right across chunk boundaries, CRLF line ends, a byte-order mark, a missing final
// newline, the first error in file order whichever thread meets it, and the same table for 1 and 2
// threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <fmt/core.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/csv_chunks.hpp"
#include "io/csv_table.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::expect_contains;
using test::TempDir;

/// Enough rows for several 4 MiB chunks (about 13 MB), with comment and blank lines between, so
/// that rows and lines differ. Row k holds k and k / 8.
std::string long_csv(const std::string& line_end) {
  std::string s = "# exported" + line_end + "id,value" + line_end;
  for (int k = 0; k < 600'000; ++k) {
    if (k % 1000 == 0) s += line_end + "# block " + std::to_string(k) + line_end;
    s += fmt::format("{},{}{}", k, k / 8.0, line_end);
  }
  return s;
}

struct Converted {
  std::vector<std::int64_t> id;
  std::vector<double> value;
  std::vector<int> line;
};

Converted convert(CsvTable& table) {
  Converted c;
  c.id.resize(table.size());
  c.value.resize(table.size());
  const CsvRowError error = table.convert_rows([&](std::size_t k, const CsvRow& row) {
    c.id[k] = table.integer(row, 0, "id");
    c.value[k] = table.number(row, 1, "value");
  });
  EXPECT_FALSE(error.error);
  for (std::size_t k = 0; k < table.size(); ++k) c.line.push_back(table.line(k));
  return c;
}

/// The line of row k in long_csv: 2 header lines, then per block of 1000 rows a blank and a
/// comment.
int line_of(int k) {
  return 3 + k + 2 * (k / 1000 + 1);
}

TEST(CsvTable, RowsAndLinesAcrossChunks) {
  TempDir dir;
  for (const std::string line_end : {"\n", "\r\n"}) {
    const std::string text = long_csv(line_end);
    CsvTable table = read_csv(dir.write("long.csv", text), "here");
    ASSERT_GT(index_csv_text(text, kMaxCsvLineBytes).chunks.size(), 2u);
    EXPECT_EQ(table.header, (std::vector<std::string>{"id", "value"}));
    EXPECT_EQ(table.header_line, 2);
    ASSERT_EQ(table.size(), 600'000u);
    const Converted c = convert(table);
    for (int k = 0; k < 600'000; k += 997) {
      EXPECT_EQ(c.id[static_cast<std::size_t>(k)], k);
      EXPECT_EQ(c.value[static_cast<std::size_t>(k)], k / 8.0);
      EXPECT_EQ(c.line[static_cast<std::size_t>(k)], line_of(k)) << "row " << k;
    }
    EXPECT_EQ(c.line.back(), line_of(599'999));
  }
}

TEST(CsvTable, OneAndTwoThreadsGiveTheSameTable) {
  TempDir dir;
  const std::string path = dir.write("long.csv", long_csv("\n"));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  CsvTable one = read_csv(path, "here");
  const Converted a = convert(one);
  omp_set_num_threads(2);
  CsvTable two = read_csv(path, "here");
  const Converted b = convert(two);
  omp_set_num_threads(threads);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.line, b.line);
}

TEST(CsvTable, FirstErrorInFileOrderWithItsLine) {
  TempDir dir;
  std::string text = long_csv("\n");
  // Two bad rows in different chunks; the later one is met first by the second thread.
  const auto bad = [&](int k, const std::string& field) {
    const std::string row = fmt::format("\n{},{}\n", k, k / 8.0);
    const auto at = text.find(row);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, row.size(), fmt::format("\n{},{}\n", k, field));
  };
  bad(500'000, "abc");
  bad(400'000, "x1");
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    CsvTable table = read_csv(dir.write("bad.csv", text), "here");
    const CsvRowError error =
        table.convert_rows([&](std::size_t, const CsvRow& row) { table.number(row, 1, "value"); });
    ASSERT_EQ(error.row, 400'000u);
    try {
      error.rethrow_at(400'000);
      ADD_FAILURE() << "expected the row's error";
    } catch (const InputError& e) {
      expect_contains(e.what(), {dir.path("bad.csv") + ":" + std::to_string(line_of(400'000)),
                                 "'value'", "'x1'"});
    }
  }
}

TEST(CsvTable, ByteOrderMarkCrlfAndNoFinalNewline) {
  TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  struct Case {
    std::string text;
    int header_line, second_row_line;
  };
  for (const Case& c : {Case{bom + "i,j\r\n0,1\r\n\r\n1,2", 1, 4}, Case{bom + "0,1\n1,2\n", 0, 2},
                        Case{"0,1\n# c\n1,2", 0, 3}}) {
    CsvTable table = read_csv(dir.write("b.csv", c.text), "here");
    ASSERT_EQ(table.size(), 2u) << c.text;
    std::vector<std::string> fields(4);
    table.convert_rows([&](std::size_t k, const CsvRow& row) {
      ASSERT_EQ(row.fields.size(), 2u);
      fields[2 * k] = row.fields[0];
      fields[2 * k + 1] = row.fields[1];
    });
    EXPECT_EQ(fields, (std::vector<std::string>{"0", "1", "1", "2"})) << c.text;
    EXPECT_EQ(table.header_line, c.header_line);
    EXPECT_EQ(table.line(1), c.second_row_line) << c.text;
  }
}

TEST(CsvTable, EmptyAndCommentOnlyFilesHaveNoRows) {
  TempDir dir;
  for (const std::string text : {"", "\n\n", "# only\n", "i,j\n", "i,j"}) {
    const CsvTable table = read_csv(dir.write("e.csv", text), "here");
    EXPECT_EQ(table.size(), 0u) << text;
  }
}

}  // namespace
}  // namespace bpm
