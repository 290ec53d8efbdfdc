#pragma once
/// An output folder holds one run. Every command that writes a folder (run, generate, stiffness,
/// calibrate, compare, verify cantilever) claims it before any computation:
///
/// - the folder is created and summary.json is written with "status": "running", the command line,
///   the bpmkit version and commit, the thread count, pid and host, and `owned_files`: the names (relative to the
///   folder) of every file this run may write. A bad --out fails here, at once, naming the path.
/// - A folder whose summary.json lists `owned_files` holds an earlier run: it is refused unless
///   `overwrite`, which deletes exactly those files (and their `.tmp` companions) first. A run
///   still going (its recorded pid alive on this host, a bpmkit) is refused even then.
/// - Files that no summary.json lists are the user's: they are never deleted. Those that have the
///   name of one of this run's outputs are refused even with `overwrite` (they would be replaced
///   or, left beside a shorter run, mixed with it); any other file is left alone.
/// - The run ends with summary.json rewritten: the command's own keys, then "status": "finished",
///   or "failed" with "error": the message of the exception that ended it.
///
/// An owned name may hold one `*` in its last part, which stands for one or more digits
/// (`frames/frame_*.vtp`): a long run writes thousands of frames. The results of bpmkit 0.1.0,
/// before `owned_files`, are recognised too: the summary.json of `run` and `generate` through its
/// `outputs` or `files` list and `vtk_frames` count; stiffness.json, calibration.json,
/// compare.json and cantilever.json by their keys, standing for their command's files.
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace bpm {

/// The process's command line, recorded in summary.json (main sets it once).
void set_command_line(int argc, const char* const* argv);

/// "0.1.0"; the commit of the source tree at build time ("" if it was not built from git), with
/// "-dirty" when it had uncommitted changes.
const char* bpmkit_version();
const char* bpmkit_commit();

class OutputFolder {
 public:
  /// Claims `dir` for a run of `command` that may write `outputs` (summary.json is added), as
  /// described above. Throws InputError naming the folder or file when it cannot.
  OutputFolder(std::string dir, std::string command, std::vector<std::string> outputs, bool overwrite);
  /// Claims `dir` to continue the earlier `command` run in it (`bpmkit run --resume`): its files
  /// stay. Refused (InputError) when the folder holds no run of `command`, or one that finished.
  /// `check` (if given) runs after those checks and before the folder is changed (summary.json
  /// "running"): the caller's own reasons to refuse.
  static OutputFolder resume(std::string dir, std::string command, std::vector<std::string> outputs,
                             const std::function<void()>& check = {});

  /// Under mpirun every rank computes, and rank 0 alone writes (solvers/mpi_world.hpp): in the other
  /// ranks' processes no folder is claimed and write() and run() write nothing.
  static void silence_this_process();
  static bool silent();

  const std::string& dir() const { return dir_; }
  /// dir/name as a string.
  std::string path(std::string_view name) const;
  /// Writes one of the declared outputs atomically (io/atomic_file.hpp); returns its path.
  std::string write(const std::string& name, std::string_view content) const;
  /// dir/name for a declared output the caller writes itself (a streamed table).
  std::string output_path(const std::string& name) const;

  /// Runs `body`, which computes and writes the results and returns the command's summary; then
  /// summary.json is that summary plus "status": "finished" (or the summary's own "status", e.g.
  /// "interrupted"). An exception from `body` marks the run "failed" with its message ("diverged"
  /// for a DivergenceError, with the message also as "reason") and is thrown on.
  void run(const std::function<nlohmann::json()>& body);

 private:
  struct ResumeTag {};
  OutputFolder(ResumeTag, std::string dir, std::string command, std::vector<std::string> outputs,
               const std::function<void()>& check);
  void write_summary(nlohmann::json summary, std::string_view status, const std::string& error) const;

  std::string dir_;
  std::string command_;
  std::vector<std::string> outputs_;
  std::string started_;
};

/// Files that belong together (generate's particles, bonds, VTK and scenario) written as one set:
/// each goes into the staging subfolder `DIR/STAGING/` first, and commit() renames them all into
/// place, so a write that fails (disk full, killed) never leaves new particles beside old bonds or
/// none. The staged names are declared outputs of the folder too (staged_outputs), so that
/// --overwrite removes what a killed run left there.
class StagedFiles {
 public:
  StagedFiles(const OutputFolder& folder, std::string staging);
  /// Removes the staged files still there (all of them unless committed) and the empty subfolder.
  ~StagedFiles();
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;

  /// Writes `name` (a declared output) into the staging subfolder.
  void write(const std::string& name, std::string_view content);
  /// Renames every staged file into place; returns their final paths, in the order written.
  std::vector<std::string> commit();

 private:
  const OutputFolder& folder_;
  std::string staging_;
  std::vector<std::string> names_;
};

/// `names` and, for each, its staged name STAGING/NAME: the outputs to declare for StagedFiles.
std::vector<std::string> staged_outputs(std::vector<std::string> names, const std::string& staging);

}  // namespace bpm
