#pragma once
/// A result table (CSV) written as the run goes: each append is one write(2) straight to the file,
/// so the rows are in the file as soon as they are computed and a run killed at any moment leaves
/// whole rows up to its last output (a write of a few kilobytes to a local file is not cut short
/// by a signal). A resumed run continues the file after the length its checkpoint recorded.
#include <cstdint>
#include <string>
#include <string_view>

namespace bpm {

class TableStream {
 public:
  TableStream() = default;
  ~TableStream();
  TableStream(const TableStream&) = delete;
  TableStream& operator=(const TableStream&) = delete;

  /// Creates (or empties) `path` and writes `header`. Throws InputError naming the path.
  void create(const std::string& path, std::string_view header);
  /// Opens `path` to continue after its first `bytes` bytes; anything after them (rows written
  /// after the checkpoint) is cut off. Throws InputError if the file is missing or shorter.
  void resume(const std::string& path, std::uint64_t bytes);
  void append(std::string_view rows);

  bool is_open() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  std::uint64_t bytes() const { return bytes_; }  ///< the file's length so far

 private:
  std::string path_;
  int fd_ = -1;
  std::uint64_t bytes_ = 0;
};

}  // namespace bpm
