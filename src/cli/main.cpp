// bpmkit command line: `bpmkit run`, `bpmkit verify cantilever`, `bpmkit generate`, and the fast
// calibration commands `bpmkit stiffness`, `bpmkit calibrate`, `bpmkit compare`. With no
// subcommand it runs the main job, the cantilever verification suite on its embedded defaults.
#include <fmt/core.h>

#include <exception>

#include "cli/commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"bpmkit: bonded-particle models for DEM (Chen 2022 unified bond law)"};
  app.set_version_flag("--version", "bpmkit 0.1.0");
  bpm::cli::add_run_command(app);
  bpm::cli::add_verify_command(app);
  bpm::cli::add_generate_command(app);
  bpm::cli::add_stiffness_command(app);
  bpm::cli::add_calibrate_command(app);
  bpm::cli::add_compare_command(app);
  try {
    app.parse(argc, argv);
    if (app.get_subcommands().empty()) {
      fmt::print("No command given: running the main job, `bpmkit verify cantilever`.\n"
                 "(`bpmkit --help` lists the commands.)\n\n");
      return bpm::cli::run_cantilever_suite({}) > 0 ? 1 : 0;
    }
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const bpm::InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
