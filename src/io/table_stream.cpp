#include "io/table_stream.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "core/error.hpp"

namespace bpm {

TableStream::~TableStream() {
  if (fd_ >= 0) ::close(fd_);
}

void TableStream::create(const std::string& path, std::string_view header) {
  if (fd_ >= 0) ::close(fd_);
  path_ = path;
  bytes_ = 0;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(path, std::string("cannot open for writing: ") + std::strerror(errno),
                     "check permissions");
  append(header);
}

void TableStream::resume(const std::string& path, std::uint64_t bytes) {
  if (fd_ >= 0) ::close(fd_);
  path_ = path;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  struct stat st {};
  if (fd_ < 0 || ::fstat(fd_, &st) != 0 || static_cast<std::uint64_t>(st.st_size) < bytes) {
    throw InputError(
        path, "is missing or shorter than when the checkpoint was written",
        "the folder was changed since; run the scenario again from the start with --overwrite");
  }
  if (::ftruncate(fd_, static_cast<off_t>(bytes)) != 0 ||
      ::lseek(fd_, static_cast<off_t>(bytes), SEEK_SET) < 0) {
    throw InputError(path,
                     std::string("cannot cut it back to the checkpoint: ") + std::strerror(errno),
                     "check permissions");
  }
  bytes_ = bytes;
}

void TableStream::append(std::string_view rows) {
  while (!rows.empty()) {
    const ssize_t n = ::write(fd_, rows.data(), rows.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw InputError(path_, std::string("write failed: ") + std::strerror(errno),
                       "check free disk space");
    rows.remove_prefix(static_cast<std::size_t>(n));
    bytes_ += static_cast<std::uint64_t>(n);
  }
}

}  // namespace bpm
