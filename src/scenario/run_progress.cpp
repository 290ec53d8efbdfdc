#include "scenario/run_progress.hpp"

#include <fmt/core.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "dem/simulation.hpp"
#include "io/log.hpp"
#include "scenario/scenario.hpp"

namespace bpm {
namespace {

/// The reporter whose terminal line log lines clear first (log::before_line).
RunProgress* active_progress = nullptr;

void clear_active_line() {
  if (active_progress != nullptr) active_progress->clear_line();
}

/// 75 s as "1m15s", 4000 s as "1h06m": the wall time and ETA at a glance.
std::string duration_text(double seconds) {
  const auto s = static_cast<std::int64_t>(std::llround(seconds));
  if (s < 60) return fmt::format("{}s", s);
  if (s < 3600) return fmt::format("{}m{:02d}s", s / 60, s % 60);
  return fmt::format("{}h{:02d}m", s / 3600, (s % 3600) / 60);
}

/// Terminal columns of `out`, 0 if unknown.
std::size_t terminal_width(std::FILE* out) {
  winsize size{};
  if (::ioctl(::fileno(out), TIOCGWINSZ, &size) != 0) return 0;
  return size.ws_col;
}

// The clock is read once per stride of steps; the stride doubles or halves to keep the reads
// about this far apart.
constexpr double kCheckSeconds = 0.05;
constexpr std::int64_t kMaxStride = std::int64_t{1} << 24;

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

ProgressPlan progress_plan(const UniaxialCompression& c) {
  // The platen moves at strain_rate * l for final_strain * l (uniaxial_compression.cpp).
  ProgressPlan plan;
  const double final_strain = c.failure_drop > 0.0 ? c.max_strain : c.target_strain;
  if (c.strain_rate > 0.0) plan.end_time = final_strain / c.strain_rate;
  return plan;
}

ProgressPlan progress_plan(const Scenario& scenario) {
  if (scenario.compression) return progress_plan(*scenario.compression);
  ProgressPlan plan;
  plan.end_time = scenario.stop.end_time;
  plan.max_steps = scenario.stop.max_steps;
  plan.rest_speed = scenario.stop.rest_speed;
  return plan;
}

std::string progress_text(const ProgressSnapshot& s) {
  std::string text = fmt::format("step {}  t = {:.4g} s", s.step, s.time);
  if (s.fraction >= 0.0) text += fmt::format(" ({:.1f} %)", 100.0 * std::min(s.fraction, 1.0));
  text += "  wall " + duration_text(s.wall_seconds);
  if (s.eta_seconds >= 0.0) text += "  ETA " + duration_text(s.eta_seconds);
  text += fmt::format("  {:.3g} bond updates/s", s.bond_updates_per_second);
  if (s.max_speed >= 0.0)
    text += fmt::format("  speed {:.3g} m/s (rest < {:.3g})", s.max_speed, s.rest_speed);
  text += fmt::format("  {} broken", s.bonds_broken);
  if (s.list_builds >= 0) text += fmt::format("  {} list builds", s.list_builds);
  return text;
}

RunProgress::RunProgress(const ProgressPlan& plan, std::FILE* out, const Settings& settings)
    : plan_(plan), out_(out), settings_(settings), started_(Clock::now()) {
  last_line_ = last_breaks_ = started_;
  active_progress = this;
  log::before_line = clear_active_line;
}

RunProgress::Settings RunProgress::settings_for(std::FILE* out, bool verbose) {
  Settings s;
  s.terminal = ::isatty(::fileno(out)) != 0;
  s.line_interval_s = s.terminal ? 0.25 : 10.0;
  s.break_interval_s = s.terminal ? 2.0 : 10.0;
  s.verbose = verbose;
  return s;
}

RunProgress::~RunProgress() {
  finish();
  if (active_progress == this) {
    active_progress = nullptr;
    log::before_line = nullptr;
  }
}

void RunProgress::finish() {
  clear_line();
  if (breaks_seen_ <= breaks_reported_) return;
  print_breaks(time_seen_, breaks_seen_);
}

void RunProgress::print_breaks(double time, std::size_t total) {
  fmt::print(out_, "t = {:.6g} s: {} bond{} broke (total {})\n", time, total - breaks_reported_,
             total - breaks_reported_ == 1 ? "" : "s", total);
  std::fflush(out_);
  breaks_reported_ = total;
}

void RunProgress::clear_line() {
  if (!line_shown_) return;
  std::fputs("\r\033[K", out_);
  std::fflush(out_);
  line_shown_ = false;
}

void RunProgress::restart(const Simulation& sim, Clock::time_point now) {
  // The last simulation's breaks first; a resumed run's earlier breaks are not news.
  if (breaks_seen_ > breaks_reported_) {
    clear_line();
    print_breaks(time_seen_, breaks_seen_);
  }
  breaks_reported_ = breaks_seen_ = sim.model().bonds.breaks.size();
  sim_ = &sim;
  first_step_ = sim.steps();
  sim_started_ = now;
  first_fraction_ = std::max(0.0, snapshot(sim, now).fraction);
  stride_ = 1;
}

ProgressSnapshot RunProgress::snapshot(const Simulation& sim, Clock::time_point now) const {
  ProgressSnapshot s;
  s.step = sim.steps();
  s.time = sim.time();
  if (std::isfinite(plan_.end_time) && plan_.end_time > 0.0) {
    s.fraction = sim.time() / plan_.end_time;
  } else if (plan_.max_steps < std::numeric_limits<std::int64_t>::max() && plan_.max_steps > 0) {
    s.fraction = static_cast<double>(sim.steps()) / static_cast<double>(plan_.max_steps);
  }
  s.wall_seconds = seconds_between(started_, now);
  const double elapsed = seconds_between(sim_started_, now);
  if (s.fraction > first_fraction_ && elapsed > 0.0 && s.fraction <= 1.0) {
    s.eta_seconds = elapsed * (1.0 - s.fraction) / (s.fraction - first_fraction_);
  }
  if (elapsed > 0.0) {
    s.bond_updates_per_second = static_cast<double>(sim.steps() - first_step_) *
                                static_cast<double>(sim.model().bonds.size()) / elapsed;
  }
  if (plan_.rest_speed > 0.0) {
    s.max_speed = sim.max_speed();
    s.rest_speed = plan_.rest_speed;
  }
  s.bonds_broken = sim.model().bonds.breaks.size();
  if (settings_.verbose && sim.contacts_on()) s.list_builds = sim.contacts().list().builds();
  return s;
}

void RunProgress::report_breaks(const Simulation& sim, Clock::time_point now) {
  const std::size_t total = sim.model().bonds.breaks.size();
  breaks_seen_ = total;
  time_seen_ = sim.time();
  if (total <= breaks_reported_ || seconds_between(last_breaks_, now) < settings_.break_interval_s)
    return;
  clear_line();
  print_breaks(sim.time(), total);
  last_breaks_ = now;
}

void RunProgress::run_ended(const Simulation& sim) {
  if (&sim != sim_) return;  // a simulation this progress never saw step
  breaks_seen_ = sim.model().bonds.breaks.size();
  time_seen_ = sim.time();
}

std::int64_t RunProgress::after_step(const Simulation& sim) {
  const Clock::time_point now = Clock::now();
  if (&sim != sim_ || sim.steps() < last_call_step_) restart(sim, now);
  // Keep the clock reads about kCheckSeconds apart whatever the step time.
  const double since_call = seconds_between(last_call_, now);
  if (since_call < 0.5 * kCheckSeconds) {
    stride_ = std::min(2 * stride_, kMaxStride);
  } else if (since_call > 2.0 * kCheckSeconds) {
    stride_ = std::max<std::int64_t>(1, stride_ / 2);
  }
  last_call_ = now;
  last_call_step_ = sim.steps();

  report_breaks(sim, now);
  if (seconds_between(last_line_, now) >= settings_.line_interval_s) {
    last_line_ = now;
    std::string text = progress_text(snapshot(sim, now));
    if (settings_.terminal) {
      // A line wider than the terminal wraps, and the carriage return would rewrite only its tail.
      const std::size_t width = terminal_width(out_);
      if (width > 1 && text.size() >= width) text.resize(width - 1);
      fmt::print(out_, "\r{}\033[K", text);
      line_shown_ = true;
    } else {
      fmt::print(out_, "progress: {}\n", text);
    }
    std::fflush(out_);
  }
  return sim.steps() + stride_;
}

}  // namespace bpm
