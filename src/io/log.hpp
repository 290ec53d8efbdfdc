#pragma once
/// The CLI's verbosity, over fmt: a command's result lines are printed always (fmt::print), its
/// informational lines through log::info (hidden by --quiet) and its details through log::detail
/// (shown by --verbose). Warnings go to stderr always: a result that may be wrong is worth a line
/// even under --quiet. Errors are not logged here: main() prints them. A few lines per command, so
/// a level check and fmt are all it needs (docs/architecture.md says why not spdlog).
#include <fmt/core.h>

#include <cstdio>
#include <utility>

namespace bpm::log {

enum class Verbosity { quiet, normal, verbose };

/// Set once by main() from --quiet / --verbose, before any command runs.
inline Verbosity verbosity = Verbosity::normal;

inline bool shows_info() {
  return verbosity != Verbosity::quiet;
}
inline bool shows_detail() {
  return verbosity == Verbosity::verbose;
}

/// Called before a log line is written (the progress line clears itself from the terminal).
inline void (*before_line)() = nullptr;

/// A result line: printed at every verbosity (a progress line on the terminal is cleared first).
template <typename... Args>
void result(fmt::format_string<Args...> format, Args&&... args) {
  if (before_line) before_line();
  fmt::print(format, std::forward<Args>(args)...);
}

template <typename... Args>
void info(fmt::format_string<Args...> format, Args&&... args) {
  if (!shows_info()) return;
  if (before_line) before_line();
  fmt::print(format, std::forward<Args>(args)...);
}

template <typename... Args>
void detail(fmt::format_string<Args...> format, Args&&... args) {
  if (!shows_detail()) return;
  if (before_line) before_line();
  fmt::print(format, std::forward<Args>(args)...);
}

template <typename... Args>
void warn(fmt::format_string<Args...> format, Args&&... args) {
  if (before_line) before_line();
  fmt::print(stderr, format, std::forward<Args>(args)...);
}

}  // namespace bpm::log
