#include "io/output_folder.hpp"

#include <fmt/core.h>
#include <omp.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "build_info.hpp"  // BPMKIT_COMMIT, generated at build time (cmake/BuildInfo.cmake)
#include "core/error.hpp"
#include "dem/simulation.hpp"  // DivergenceError
#include "io/atomic_file.hpp"

namespace bpm {
namespace {

namespace fs = std::filesystem;

std::string& command_line_text() {
  static std::string text;
  return text;
}

/// A name may only point inside the folder: an edited or foreign summary.json must not make
/// --overwrite delete anything elsewhere.
bool inside(const std::string& name) {
  const fs::path p(name);
  if (name.empty() || p.is_absolute() || p.has_root_name()) return false;
  for (const auto& part : p) {
    if (part == ".." || part == ".") return false;
  }
  // At most one `*`, in the last part: it never matches a folder.
  const auto stars = std::count(name.begin(), name.end(), '*');
  return stars == 0 || (stars == 1 && p.filename().string().find('*') != std::string::npos);
}

/// `name` is `pattern`, or `pattern` with its `*` standing for one or more digits.
bool matches(std::string_view pattern, std::string_view name) {
  const auto star = pattern.find('*');
  if (star == std::string_view::npos) return pattern == name;
  const std::string_view prefix = pattern.substr(0, star), suffix = pattern.substr(star + 1);
  if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix)) return false;
  const std::string_view digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// `name` is one of `patterns` or its `.tmp` companion (what write_file_atomic leaves when killed).
bool owned_by(const std::vector<std::string>& patterns, const std::string& name) {
  return std::any_of(patterns.begin(), patterns.end(),
                     [&](const std::string& p) { return matches(p, name) || matches(p + ".tmp", name); });
}

/// The files in `dir` (names relative to it) that `pattern` or its `.tmp` companion names.
std::vector<std::string> existing(const fs::path& dir, const std::string& pattern) {
  std::vector<std::string> found;
  std::error_code ec;
  const fs::path parent = fs::path(pattern).parent_path();
  if (pattern.find('*') == std::string::npos) {
    for (const std::string& name : {pattern, pattern + ".tmp"}) {
      const fs::file_status s = fs::symlink_status(dir / name, ec);
      if (fs::exists(s) && !fs::is_directory(s)) found.push_back(name);
    }
    return found;
  }
  if (!fs::is_directory(dir / parent, ec)) return found;
  for (const auto& entry : fs::directory_iterator(dir / parent, ec)) {
    if (entry.is_directory(ec)) continue;
    const std::string name = (parent / entry.path().filename()).generic_string();
    if (matches(pattern, name) || matches(pattern + ".tmp", name)) found.push_back(name);
  }
  std::sort(found.begin(), found.end());
  return found;
}

/// What an earlier run's summary.json says it owns.
struct EarlierRun {
  bool found = false;
  std::string command, status;
  std::vector<std::string> owned;
  long pid = 0;      ///< the process that wrote it (0: not recorded)
  std::string host;  ///< and its machine
};

std::string this_host() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "";
  return name;
}

/// Whether the run behind a "running" summary.json is still going: its process is alive on this
/// machine and is a bpmkit (the name of its executable; a reused pid is another program). A
/// process of another user, whose executable cannot be read, counts as alive: better refused
/// than two runs writing one folder. A run on another machine (a shared file system) cannot be
/// checked and is not refused.
bool still_running(const EarlierRun& e) {
  if (e.status != "running" || e.pid <= 0 || e.host.empty() || e.host != this_host()) return false;
  if (e.pid == static_cast<long>(::getpid())) return false;  // this process (a resume in a test)
  if (::kill(static_cast<pid_t>(e.pid), 0) != 0 && errno != EPERM) return false;
  std::error_code ec;
  const fs::path exe = fs::read_symlink(fs::path("/proc") / std::to_string(e.pid) / "exe", ec);
  return ec || exe.filename().string().starts_with("bpmkit");
}

/// Refuses a folder whose run is still going, for --overwrite and --resume alike.
void refuse_if_running(const std::string& dir, const EarlierRun& e) {
  if (!still_running(e)) return;
  throw InputError(dir, fmt::format("is the folder of a `bpmkit {}` that is still running (process {})", e.command, e.pid),
                   fmt::format("wait for it to end, or stop it first (kill {}: a run writes a checkpoint and stops), "
                               "or choose another --out",
                               e.pid));
}

/// The JSON object in `path`; null if missing or not JSON.
nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return nullptr;
  nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return j.is_object() ? j : nlohmann::json(nullptr);
}

/// bpmkit 0.1.0's stiffness, calibrate, compare and verify wrote no summary.json: their result
/// file, recognised by its keys, stands for the files of that run.
struct LegacyResult {
  const char* file;
  std::vector<const char*> keys;
  std::vector<std::string> owned;
  const char* command;
};
const std::vector<LegacyResult>& legacy_results() {
  static const std::vector<LegacyResult> list = {
      {"stiffness.json", {"method", "stiffness_N_per_m", "details"},
       {"stiffness.json", "displacement.vtp", "stiffness_map.vtp"}, "stiffness"},
      {"calibration.json", {"stages", "target_stiffness_N_per_m"}, {"calibration.json"}, "calibrate"},
      {"compare.json", {"rows", "reference"}, {"compare.json", "compare.csv"}, "compare"},
      {"cantilever.json", {"suite", "runs", "case3_stiffness"},
       {"cantilever.json", "cantilever_tips.csv", "case1_deflection.csv", "case3_stiffness.csv"}, "verify cantilever"}};
  return list;
}

EarlierRun read_legacy_result(const fs::path& dir) {
  EarlierRun earlier;
  for (const LegacyResult& r : legacy_results()) {
    const nlohmann::json j = read_json(dir / r.file);
    if (j.is_null() || !std::all_of(r.keys.begin(), r.keys.end(), [&](const char* k) { return j.contains(k); })) continue;
    earlier.found = true;
    earlier.command = r.command;
    earlier.status = "finished";
    earlier.owned = r.owned;
    break;
  }
  return earlier;
}

EarlierRun read_earlier_run(const fs::path& dir) {
  EarlierRun earlier;
  const nlohmann::json j = read_json(dir / "summary.json");
  if (j.is_null()) return read_legacy_result(dir);  // none, or not JSON: a foreign file
  auto strings = [&](const char* key) {
    std::vector<std::string> list;
    if (j.contains(key) && j[key].is_array()) {
      for (const auto& v : j[key]) {
        if (v.is_string()) list.push_back(v.get<std::string>());
      }
    }
    return list;
  };
  if (j.contains("owned_files") && j["owned_files"].is_array()) {
    earlier.command = j.value("command", std::string("?"));
    earlier.status = j.value("status", std::string("?"));
    if (j.contains("pid") && j["pid"].is_number_integer()) earlier.pid = j["pid"].get<long>();
    earlier.host = j.value("host", std::string());
    for (const std::string& name : strings("owned_files")) {
      if (inside(name)) earlier.owned.push_back(name);
    }
  } else if (j.contains("outputs") && j.contains("stop_reason")) {  // bpmkit 0.1.0 `run`
    earlier.command = "run";
    for (const std::string& path : strings("outputs")) earlier.owned.push_back(fs::path(path).filename().string());
    if (j.value("vtk_frames", 0) > 0) earlier.owned.push_back("frames/frame_*.vtp");
  } else if (j.contains("files") && j.contains("seed") && j.contains("particles")) {  // bpmkit 0.1.0 `generate`
    earlier.command = "generate";
    for (const std::string& path : strings("files")) earlier.owned.push_back(fs::path(path).filename().string());
  } else {
    return read_legacy_result(dir);  // a summary.json bpmkit did not write
  }
  if (earlier.status.empty()) earlier.status = "finished";
  earlier.owned.push_back("summary.json");
  earlier.found = true;
  return earlier;
}

std::string list_some(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < 5; ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > 5) text += fmt::format(" and {} more", names.size() - 5);
  return text;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace

void set_command_line(int argc, const char* const* argv) {
  std::string& text = command_line_text();
  text.clear();
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool plain = !arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                             "0123456789-_./=:,+@%") == std::string::npos;
    if (i > 0) text += ' ';
    if (plain) {
      text += arg;
      continue;
    }
    // Quoted so that it can be pasted back into a shell.
    text += '\'';
    for (const char c : arg) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
    text += '\'';
  }
}

const char* bpmkit_version() { return BPMKIT_VERSION; }
const char* bpmkit_commit() { return BPMKIT_COMMIT; }

namespace {
bool silent_process = false;  // set once, by main, before any command runs
}  // namespace

void OutputFolder::silence_this_process() { silent_process = true; }
bool OutputFolder::silent() { return silent_process; }

OutputFolder::OutputFolder(std::string dir, std::string command, std::vector<std::string> outputs, bool overwrite)
    : dir_(std::move(dir)), command_(std::move(command)), outputs_(std::move(outputs)) {
  if (std::find(outputs_.begin(), outputs_.end(), "summary.json") == outputs_.end()) outputs_.push_back("summary.json");
  if (silent_process) return;
  const fs::path d(dir_);
  std::error_code ec;
  if (fs::exists(d, ec) && !fs::is_directory(d, ec)) {
    throw InputError(dir_, "is a file, not a folder", "give --out a folder (it is created if missing)");
  }
  fs::create_directories(d, ec);
  if (ec) throw InputError(dir_, "cannot create the output folder: " + ec.message(), "check the path and its permissions");

  const EarlierRun earlier = read_earlier_run(d);
  // Files this run would write over that no earlier run listed: the user's, never deleted.
  std::vector<std::string> foreign;
  for (const std::string& output : outputs_) {
    for (std::string& name : existing(d, output)) {
      if (!owned_by(earlier.owned, name)) foreign.push_back(std::move(name));
    }
  }
  refuse_if_running(dir_, earlier);
  if (earlier.found && !overwrite) {
    throw InputError(dir_,
                     fmt::format("holds the results of an earlier `bpmkit {}` (status: {}); an output folder is one run",
                                 earlier.command, earlier.status),
                     "give --overwrite to delete the files its summary.json lists and run again, or choose another --out");
  }
  if (!foreign.empty()) {
    throw InputError(dir_,
                     "holds files that bpmkit did not write (no summary.json there lists them) under the names of this "
                     "run's outputs: " + list_some(foreign),
                     "move or delete them yourself, or choose another --out; --overwrite deletes only files an earlier "
                     "run listed");
  }
  if (earlier.found) {
    // summary.json last: a removal that fails half-way leaves the list for the next try.
    std::vector<std::string> doomed;
    for (const std::string& pattern : earlier.owned) {
      for (std::string& name : existing(d, pattern)) doomed.push_back(std::move(name));
    }
    std::stable_partition(doomed.begin(), doomed.end(), [](const std::string& n) { return n != "summary.json"; });
    for (const std::string& name : doomed) {
      if (!fs::remove(d / name, ec) && ec) {
        throw InputError((d / name).string(), "cannot delete the earlier run's file: " + ec.message(), "check permissions");
      }
    }
    // Subfolders (frames/) that held only the earlier run's files go too.
    for (const std::string& pattern : earlier.owned) {
      const fs::path parent = fs::path(pattern).parent_path();
      if (!parent.empty() && fs::is_directory(d / parent, ec) && fs::is_empty(d / parent, ec)) fs::remove(d / parent, ec);
    }
  }
  started_ = utc_now();
  // Also the check that the folder can be written, before any computation.
  write_summary(nlohmann::json::object(), "running", "");
}

OutputFolder OutputFolder::resume(std::string dir, std::string command, std::vector<std::string> outputs,
                                  const std::function<void()>& check) {
  return OutputFolder(ResumeTag{}, std::move(dir), std::move(command), std::move(outputs), check);
}

OutputFolder::OutputFolder(ResumeTag, std::string dir, std::string command, std::vector<std::string> outputs,
                           const std::function<void()>& check)
    : dir_(std::move(dir)), command_(std::move(command)), outputs_(std::move(outputs)) {
  if (std::find(outputs_.begin(), outputs_.end(), "summary.json") == outputs_.end()) outputs_.push_back("summary.json");
  const EarlierRun earlier = read_earlier_run(fs::path(dir_));
  if (!earlier.found) {
    throw InputError(dir_, "holds no run to resume (no summary.json of bpmkit there)",
                     "give --resume the --out folder of the run to continue");
  }
  if (earlier.command != command_) {
    throw InputError(dir_, fmt::format("holds a `bpmkit {}` run, not a `bpmkit {}` run", earlier.command, command_),
                     "give --resume the --out folder of the run to continue");
  }
  refuse_if_running(dir_, earlier);
  if (earlier.status == "finished") {
    throw InputError(dir_, "holds a run that finished: there is nothing to resume",
                     "to run it again, give --overwrite instead of --resume");
  }
  if (check) check();
  started_ = utc_now();
  write_summary(nlohmann::json::object(), "running", "");
}

std::string OutputFolder::output_path(const std::string& name) const {
  if (!owned_by(outputs_, name)) throw std::logic_error("bpmkit " + command_ + " writes undeclared output " + name);
  return path(name);
}

std::string OutputFolder::path(std::string_view name) const { return (fs::path(dir_) / name).string(); }

std::string OutputFolder::write(const std::string& name, std::string_view content) const {
  // Every file must be in owned_files, or an --overwrite would leave it behind.
  if (!owned_by(outputs_, name)) throw std::logic_error("bpmkit " + command_ + " writes undeclared output " + name);
  const std::string p = path(name);
  if (!silent_process) write_file_atomic(p, content);
  return p;
}

void OutputFolder::run(const std::function<nlohmann::json()>& body) {
  if (silent_process) {
    body();
    return;
  }
  nlohmann::json summary;
  try {
    summary = body();
  } catch (const std::exception& e) {
    try {
      nlohmann::json failure = nlohmann::json::object();
      const bool diverged = dynamic_cast<const DivergenceError*>(&e) != nullptr;
      if (diverged) failure["reason"] = e.what();
      write_summary(std::move(failure), diverged ? "diverged" : "failed", e.what());
    } catch (const std::exception&) {
      // The original error is the one to report.
    }
    throw;
  }
  const std::string status = summary.value("status", std::string("finished"));
  write_summary(std::move(summary), status, "");
}

StagedFiles::StagedFiles(const OutputFolder& folder, std::string staging)
    : folder_(folder), staging_(std::move(staging)) {}

StagedFiles::~StagedFiles() {
  std::error_code ec;
  for (const std::string& name : names_) {
    for (const std::string& file : {staging_ + "/" + name, staging_ + "/" + name + ".tmp"}) {
      if (!fs::is_directory(fs::symlink_status(folder_.path(file), ec))) fs::remove(folder_.path(file), ec);
    }
  }
  // Only when empty: a file there that is not ours stays.
  if (fs::is_directory(folder_.path(staging_), ec) && fs::is_empty(folder_.path(staging_), ec)) {
    fs::remove(folder_.path(staging_), ec);
  }
}

void StagedFiles::write(const std::string& name, std::string_view content) {
  names_.push_back(name);
  folder_.write(staging_ + "/" + name, content);
}

std::vector<std::string> StagedFiles::commit() {
  // Renames within one file system: no data is written, so nothing here runs out of space.
  std::vector<std::string> paths;
  for (const std::string& name : names_) {
    std::error_code ec;
    paths.push_back(folder_.path(name));
    fs::rename(folder_.path(staging_ + "/" + name), paths.back(), ec);
    if (ec) throw InputError(paths.back(), "cannot move the written file into place: " + ec.message(), "check permissions");
  }
  return paths;
}

std::vector<std::string> staged_outputs(std::vector<std::string> names, const std::string& staging) {
  const std::size_t n = names.size();
  for (std::size_t i = 0; i < n; ++i) names.push_back(staging + "/" + names[i]);
  return names;
}

void OutputFolder::write_summary(nlohmann::json summary, std::string_view status, const std::string& error) const {
  summary["status"] = status;
  if (!error.empty()) summary["error"] = error;
  summary["command"] = command_;
  summary["command_line"] = command_line_text();
  summary["bpmkit_version"] = bpmkit_version();
  summary["commit"] = *bpmkit_commit() ? nlohmann::json(bpmkit_commit()) : nlohmann::json(nullptr);
  if (!summary.contains("threads")) summary["threads"] = omp_get_max_threads();
  summary["started"] = started_;
  summary["pid"] = static_cast<long>(::getpid());  // another bpmkit refuses the folder while it runs
  summary["host"] = this_host();
  if (status != "running") summary["ended"] = utc_now();
  summary["owned_files"] = outputs_;
  write_file_atomic(path("summary.json"), summary.dump(2) + "\n");
}

}  // namespace bpm
