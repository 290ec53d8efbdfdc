#include "cli/wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>

namespace bpm::cli {

void reexec_with_passive_wait_policy(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  // Set before the exec, so the new image's libgomp reads it, and so that it never loops.
  if (::setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  ::execv("/proc/self/exe", argv);
}

}  // namespace bpm::cli
