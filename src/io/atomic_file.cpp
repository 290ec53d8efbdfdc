#include "io/atomic_file.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/error.hpp"

namespace bpm {

void write_file_atomic(const std::string& path, std::string_view content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  if (ec) throw InputError(path, "cannot create the directory: " + ec.message(), "check the output path");
  const fs::path tmp = target.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "cannot open for writing", "check permissions and free space");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw InputError(path, "write failed", "check free disk space");
  }
  fs::rename(tmp, target, ec);
  if (ec) throw InputError(path, "cannot replace the file: " + ec.message(), "check permissions");
}

}  // namespace bpm
