// bpmkit command line: `bpmkit run`, `bpmkit verify cantilever`, `bpmkit generate`, the fast
// calibration commands `bpmkit stiffness`, `bpmkit calibrate`, `bpmkit compare`, `bpmkit convert` and
// `bpmkit export lammps` (other codes' formats), and `bpmkit plot`
// (figures of an output folder). With no arguments it prints the help. Exit status: 0 success,
// 1 a failed run or check, 2 a usage error (unknown option, missing argument, bad subcommand) or an
// input error.
#include <fmt/core.h>

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "cli/application.hpp"
#include "cli/runtime_environment.hpp"
#include "core/error.hpp"
#include "io/output_folder.hpp"

int main(int argc, char** argv) {
  // Sleeping OpenMP threads and huge pages (cli/runtime_environment.hpp): may exec once.
  bpm::cli::reexec_with_runtime_environment(argv);
  // Line-buffered stdout: through a pipe or into a log (tee, the validation study) each status
  // line arrives when printed, not when the block buffer fills or the run ends. One setting here
  // covers every command's lines; they are few (no per-step output), so a write per line costs
  // nothing measurable. stderr is unbuffered anyway.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  bpm::set_command_line(argc, argv);
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
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    // Inputs are checked against their size limits; this is what slipped past them.
    fmt::print(stderr, "error: out of memory (std::bad_alloc): the input needs more memory than this process may use "
                       "(free memory, ulimit -v); use a smaller model\n");
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
