#pragma once
/// Errors the user can act on. An InputError names where the problem is (file, line or key) and
/// what to do about it; the CLI prints it and exits non-zero. BPM_ASSERT guards internal
/// invariants in debug and sanitizer builds only.
#include <cassert>
#include <stdexcept>
#include <string>

namespace bpm {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& where, const std::string& what, const std::string& fix = "")
      : std::runtime_error(where + ": " + what + (fix.empty() ? "" : " (" + fix + ")")) {}
};

}  // namespace bpm

#define BPM_ASSERT(cond) assert(cond)
