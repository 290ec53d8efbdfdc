// bpmkit command line: `bpmkit run`, `bpmkit verify cantilever`, `bpmkit generate`, the fast
// calibration commands `bpmkit stiffness`, `bpmkit calibrate`, `bpmkit compare`, `bpmkit convert` and
// `bpmkit export lammps` (other codes' formats), and `bpmkit plot`
// (figures of an output folder). With no arguments it prints the help. Exit status: 0 success,
// 1 a failed run or check, 2 a usage error (unknown option, missing argument, bad subcommand) or an
// input error.
#include <fmt/core.h>

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <thread>

#include "cli/application.hpp"
#include "cli/runtime_environment.hpp"
#include "core/error.hpp"
#include "solvers/mpi_world.hpp"
#include "io/log.hpp"
#include "io/output_folder.hpp"

namespace {

/// Under mpirun (solvers/mpi_world.hpp): rank 0 prints and writes, the others compute silently; each
/// rank takes its share of the cores unless OMP_NUM_THREADS or --threads says otherwise (OpenMPI
/// binds a rank to one core when there are at most two).
void join_mpi_run() {
  const bpm::mpi::World world = bpm::mpi::world();
  if (!world.distributed()) return;
  if (std::getenv("OMP_NUM_THREADS") == nullptr) {
    const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    const int ranks_here = local != nullptr ? std::max(1, std::atoi(local)) : world.size;
    const int cores = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
    omp_set_num_threads(std::max(1, std::min(omp_get_num_procs(), cores / ranks_here)));
  }
  if (world.root()) return;
  bpm::OutputFolder::silence_this_process();
  bpm::log::verbosity = bpm::log::Verbosity::quiet;
  if (std::freopen("/dev/null", "w", stdout) == nullptr) std::fclose(stdout);
}

/// An error's message, from rank 0 as usual and marked with the rank from the others; under mpirun
/// the run then ends on every rank (MPI_Abort) instead of leaving them waiting in a collective.
int fail(int status, const char* message) {
  const bpm::mpi::World world = bpm::mpi::world();
  if (world.root()) fmt::print(stderr, "error: {}\n", message);
  else fmt::print(stderr, "error (MPI rank {}): {}\n", world.rank, message);
  bpm::mpi::abort_if_distributed(status);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // Sleeping OpenMP threads and huge pages (cli/runtime_environment.hpp): may exec once.
  bpm::cli::reexec_with_runtime_environment(argv);
  // Line-buffered stdout: through a pipe or into a log (tee, the validation study) each status
  // line arrives when printed, not when the block buffer fills or the run ends. One setting here
  // covers every command's lines; they are few (no per-step output), so a write per line costs
  // nothing measurable. stderr is unbuffered anyway.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  bpm::set_command_line(argc, argv);
  join_mpi_run();
  CLI::App app{"bpmkit: bonded-particle models for DEM (Chen 2022 unified bond law)"};
  bpm::cli::add_commands(app);
  try {
    app.parse(argc, argv);
    if (app.get_subcommands().empty()) {
      fmt::print("{}", app.help());
      return 0;
    }
  } catch (const CLI::RuntimeError& e) {
    // A command's own failure (verify: a check failed), not a usage error.
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with status 0; CLI11's own codes (100 and up) for usage
    // errors are replaced by the conventional 2.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const bpm::InputError& e) {
    return fail(2, e.what());
  } catch (const std::bad_alloc&) {
    // Inputs are checked against their size limits; this is what slipped past them.
    return fail(1, "out of memory (std::bad_alloc): the input needs more memory than this process may use "
                   "(free memory, ulimit -v); use a smaller model");
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
  return 0;
}
