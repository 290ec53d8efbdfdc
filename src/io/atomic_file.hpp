#pragma once
/// Writes a whole file atomically: the content goes to a temporary file in the same directory,
/// which is flushed and then renamed over the target, so a reader (or a crash) never sees a
/// half-written result. Parent directories are created. Throws InputError naming the path.
#include <string>
#include <string_view>

namespace bpm {

void write_file_atomic(const std::string& path, std::string_view content);

}  // namespace bpm
