#include "cli/application.hpp"

#include <algorithm>

#include "cli/commands.hpp"
#include "cli/global_options.hpp"
#include "core/error.hpp"
#include "io/log.hpp"
#include "io/output_folder.hpp"
#include "solvers/mpi_world.hpp"

namespace bpm::cli {

void add_commands(CLI::App& app) {
  const std::string commit = bpmkit_commit();
  app.set_version_flag("--version",
                       std::string("bpmkit ") + bpmkit_version() +
                           (commit.empty() ? std::string() : " (commit " + commit + ")"));
  // Options of the whole program, also accepted after the subcommand (`bpmkit run X --quiet`).
  app.fallthrough();
  add_global_options(app);
  add_run_command(app);
  add_verify_command(app);
  add_generate_command(app);
  add_stiffness_command(app);
  add_calibrate_command(app);
  add_compare_command(app);
  add_plot_command(app);
  add_convert_command(app);
  add_export_command(app);
  // Under mpirun only the methods divided between the ranks run: `stiffness`, `calibrate --no-dem`
  // and `compare --reference-from` check their methods themselves (issue 14).
  for (CLI::App* command : app.get_subcommands({})) {
    const std::string& name = command->get_name();
    if (name == "stiffness" || name == "calibrate" || name == "compare") continue;
    command->preparse_callback([name](std::size_t) {
      if (mpi::world().distributed()) {
        throw InputError(
            "bpmkit " + name, "does not run across MPI ranks",
            "run it without mpirun; under mpirun: bpmkit stiffness, calibrate --no-dem and compare "
            "--reference-from, with dsm, dsm-nonlinear and ste");
      }
    });
  }
}

void run_in_process(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"bpmkit"};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<const char*> pointers;
  for (const std::string& a : argv) pointers.push_back(a.c_str());
  set_command_line(static_cast<int>(pointers.size()), pointers.data());
  // --quiet and --verbose of an earlier command in this process must not stick.
  log::verbosity = log::Verbosity::normal;
  CLI::App app{"bpmkit"};
  add_commands(app);
  // CLI11 takes the arguments in reverse order (it pops them from the back).
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  app.parse(reversed);
}

}  // namespace bpm::cli
