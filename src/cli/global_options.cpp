#include "cli/global_options.hpp"

#include <omp.h>

#include "io/log.hpp"

namespace bpm::cli {

void add_global_options(CLI::App& app) {
  // An option function runs while the command line is processed, before the subcommand's
  // callback, so the thread count holds for all of its work. Without --threads the OpenMP runtime
  // has read OMP_NUM_THREADS itself.
  app.add_option_function<int>(
         "--threads", [](int threads) { omp_set_num_threads(threads); },
         "OpenMP threads (default: OMP_NUM_THREADS, else one per core); summary.json records the "
         "count")
      ->check(CLI::Range(1, 4096));
  auto* quiet = app.add_flag_callback(
      "--quiet,-q", [] { log::verbosity = log::Verbosity::quiet; },
      "only errors, warnings and the result lines: no progress line or status lines");
  auto* verbose = app.add_flag_callback(
      "--verbose,-v", [] { log::verbosity = log::Verbosity::verbose; },
      "more detail: the time step's derivation, neighbour list builds in the progress line");
  quiet->excludes(verbose);
}

bool progress_enabled() {
  return log::shows_info();
}

}  // namespace bpm::cli
