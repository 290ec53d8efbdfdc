#pragma once
/// The progress of a DEM run for a person watching it: on a terminal one status line rewritten in
/// place (carriage return) a few times per second; otherwise a plain line every few seconds. The
/// line holds the step, simulated time, percent done, wall time, ETA, bond updates per second, the
/// rest criterion's current speed and the bonds broken; breaks are also summarised as they happen
/// ("t = ...: 12 bonds broke (total 140)"), at most once per reporting interval.
///
/// It watches through the Simulation's StepMonitor hook and reads the wall clock only at a stride
/// of steps chosen so that checks come about every 50 ms: its cost stays far below 1 % of a step.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "dem/step_monitor.hpp"

namespace bpm {

struct Scenario;
struct UniaxialCompression;

/// What "done" means for the percent and the ETA.
struct ProgressPlan {
  double end_time =
      std::numeric_limits<double>::infinity();  ///< s; the percent is of this if finite
  std::int64_t max_steps =
      std::numeric_limits<std::int64_t>::max();  ///< ... else of this if finite
  double rest_speed = 0.0;  ///< m/s; > 0: show the current max speed against it
};

/// The plan of `bpmkit run SCENARIO`: the stop criteria, or the compression test's duration
/// (final strain / strain rate).
ProgressPlan progress_plan(const Scenario& scenario);
ProgressPlan progress_plan(const UniaxialCompression& compression);

/// One moment of a run, as the status line shows it.
struct ProgressSnapshot {
  std::int64_t step = 0;
  double time = 0.0;          ///< simulated, s
  double fraction = -1.0;     ///< of the plan done, 0..1; < 0 unknown
  double wall_seconds = 0.0;  ///< since the reporter started
  double eta_seconds = -1.0;  ///< < 0 unknown
  double bond_updates_per_second = 0.0;
  double max_speed = -1.0;  ///< m/s; < 0 not shown
  double rest_speed = 0.0;
  std::size_t bonds_broken = 0;
  std::int64_t list_builds = -1;  ///< neighbour list builds (--verbose); < 0 not shown
};

/// The status line's text (no newline or carriage return).
std::string progress_text(const ProgressSnapshot& s);

class RunProgress : public StepMonitor {
 public:
  struct Settings {
    bool terminal = false;          ///< rewrite one line in place (else print plain lines)
    double line_interval_s = 0.25;  ///< between status lines
    double break_interval_s = 2.0;  ///< between break summaries
    bool verbose = false;           ///< add the neighbour list builds
  };
  /// Writes to `out` (stderr in the CLI: the status is not a result).
  RunProgress(const ProgressPlan& plan, std::FILE* out, const Settings& settings);
  /// The settings for `out`: on a terminal a line every 0.25 s, otherwise every 10 s.
  static Settings settings_for(std::FILE* out, bool verbose);
  ~RunProgress() override;
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;

  std::int64_t after_step(const Simulation& sim) override;
  /// The breaks since the last clock read count towards the closing summary (finish).
  void run_ended(const Simulation& sim) override;
  /// Clears the terminal line (before other output, and at the end).
  void clear_line();
  /// Clears the line and summarises the breaks not yet reported (as of the last call).
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void restart(const Simulation& sim, Clock::time_point now);
  ProgressSnapshot snapshot(const Simulation& sim, Clock::time_point now) const;
  void report_breaks(const Simulation& sim, Clock::time_point now);
  void print_breaks(double time, std::size_t total);

  ProgressPlan plan_;
  std::FILE* out_;
  Settings settings_;
  Clock::time_point started_;
  // The simulation being watched (a command may run several in turn) and where it was first seen.
  const Simulation* sim_ = nullptr;
  std::int64_t first_step_ = 0;
  double first_fraction_ = 0.0;
  Clock::time_point sim_started_;
  // The stride between calls, adapted to the step time.
  std::int64_t stride_ = 1;
  std::int64_t last_call_step_ = 0;
  Clock::time_point last_call_;
  Clock::time_point last_line_;
  Clock::time_point last_breaks_;
  std::size_t breaks_reported_ = 0;
  // What the last call saw, for the last break summary when the reporter goes.
  std::size_t breaks_seen_ = 0;
  double time_seen_ = 0.0;
  bool line_shown_ = false;
};

}  // namespace bpm
