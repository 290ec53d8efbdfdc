#include "cli/commands.hpp"

namespace bpm::cli {
void add_run_command(CLI::App&) {}
}  // namespace bpm::cli
