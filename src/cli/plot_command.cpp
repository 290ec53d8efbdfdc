// `bpmkit plot DIR [--out OUTDIR]`: PNG and SVG figures of what a bpmkit command wrote into DIR
// (compression curve and fit, cantilever verification, stiffness methods and calibration, probe and
// wall time series). The drawing is scripts/bpmkit_plot.py with matplotlib; this command runs it
// with Debian's /usr/bin/python3 (else `python3` on PATH) and returns its exit status. The script
// is the file the environment variable BPMKIT_PLOT_SCRIPT names, else the installed copy beside an
// installed bpmkit (<prefix>/share/bpmkit/, BPMKIT_PLOT_SCRIPT_INSTALLED relative to <prefix>),
// else the one of the source tree this bpmkit was built from (BPMKIT_PLOT_SCRIPT).
#include <fmt/core.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core/error.hpp"

#ifndef BPMKIT_PLOT_SCRIPT
#define BPMKIT_PLOT_SCRIPT "scripts/bpmkit_plot.py"
#endif
#ifndef BPMKIT_PLOT_SCRIPT_INSTALLED
#define BPMKIT_PLOT_SCRIPT_INSTALLED "share/bpmkit/bpmkit_plot.py"
#endif

extern char** environ;

namespace bpm::cli {
namespace {

struct Options {
  std::string dir;
  std::string out;
};

/// <prefix>/share/bpmkit/bpmkit_plot.py when this program is <prefix>/bin/bpmkit and the file is
/// there, else empty.
std::string installed_plot_script() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const std::filesystem::path script = self.parent_path().parent_path() / BPMKIT_PLOT_SCRIPT_INSTALLED;
  return std::filesystem::is_regular_file(script, error) ? script.string() : std::string();
}

std::string plot_script() {
  const char* env = std::getenv("BPMKIT_PLOT_SCRIPT");
  const bool from_env = env != nullptr && *env != '\0';
  const std::string installed = from_env ? std::string() : installed_plot_script();
  const std::string script = from_env ? env : !installed.empty() ? installed : BPMKIT_PLOT_SCRIPT;
  if (std::error_code ignored; !std::filesystem::is_regular_file(script, ignored)) {
    throw InputError(from_env ? "BPMKIT_PLOT_SCRIPT" : "bpmkit plot",
                     "the plotting script " + script + " does not exist",
                     from_env
                         ? "set BPMKIT_PLOT_SCRIPT to scripts/bpmkit_plot.py of the bpmkit sources"
                         : "set BPMKIT_PLOT_SCRIPT to scripts/bpmkit_plot.py of the bpmkit sources "
                           "(this bpmkit was built from a source tree that has moved)");
  }
  return script;
}

/// Runs python3 SCRIPT DIR [--out OUT] (an argument vector: no shell, no quoting); returns its
/// exit status, 128 + the signal if a signal ended it.
int run_script(const Options& o) {
  const std::string script = plot_script();
  const bool debian = ::access("/usr/bin/python3", X_OK) == 0;
  const std::string python = debian ? "/usr/bin/python3" : "python3";
  std::vector<std::string> args = {python, script, o.dir};
  if (!o.out.empty()) {
    args.emplace_back("--out");
    args.push_back(o.out);
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::fflush(stdout);  // our lines before the script's
  std::fflush(stderr);
  pid_t pid = 0;
  const int rc = debian
                     ? ::posix_spawn(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ)
                     : ::posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ);
  if (rc != 0) {
    throw InputError("bpmkit plot", "cannot start " + python + ": " + std::strerror(rc),
                     "install python3 and python3-matplotlib (Debian)");
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 1;
}

}  // namespace

void add_plot_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "plot",
      "PNG and SVG figures of a bpmkit output folder (compression curve, cantilever verification, "
      "stiffness methods, calibration, probes and walls); needs python3-matplotlib");
  auto options = std::make_shared<Options>();
  cmd->add_option("dir", options->dir,
                  "output folder of a bpmkit command (run, verify cantilever, compare, ...)")
      ->required();
  cmd->add_option("--out", options->out, "write the figures into this folder instead of DIR");
  cmd->callback([options] {
    const int status = run_script(*options);
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace bpm::cli
