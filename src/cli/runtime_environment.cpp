#include "cli/runtime_environment.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace bpm::cli {

void reexec_with_runtime_environment(char** argv) {
  bool changed = false;
  // Each is set before the exec, so the new image's libraries read it, and so that it never loops.
  if (std::getenv("OMP_WAIT_POLICY") == nullptr && std::getenv("GOMP_SPINCOUNT") == nullptr) {
    changed = ::setenv("OMP_WAIT_POLICY", "passive", 1) == 0 || changed;
  }
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string own = tunables != nullptr ? tunables : "";
  if (own.find("glibc.malloc.hugetlb") == std::string::npos) {
    const std::string value = own.empty() ? "glibc.malloc.hugetlb=1" : own + ":glibc.malloc.hugetlb=1";
    changed = ::setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0 || changed;
  }
  if (changed) ::execv("/proc/self/exe", argv);
}

}  // namespace bpm::cli
