#pragma once
/// A hook for watching a long DEM run from outside (the CLI's progress line,
/// scenario/run_progress.hpp) without the library printing anything. Simulation::step calls the
/// installed monitor at the step it asked for, so the cost per step is one pointer load and one
/// comparison; the monitor picks its own stride (e.g. from the wall clock) to stay far below 1 % of
/// the step time.
///
/// One monitor per process (the CLI runs one simulation at a time); install it with
/// ScopedStepMonitor for the duration of a command.
#include <cstdint>

namespace bpm {

class Simulation;

class StepMonitor {
 public:
  virtual ~StepMonitor() = default;
  /// Called after a step; returns the step count at which to be called next (> sim.steps()). A
  /// new Simulation calls it after its first step.
  virtual std::int64_t after_step(const Simulation& sim) = 0;
  /// Called when a driver (Simulation::run, the compression test) stops stepping: what happened
  /// after the last after_step call (bonds that broke in the last steps) is not lost.
  virtual void run_ended(const Simulation& sim) { (void)sim; }
};

/// The installed monitor, or null (the default: tests and library users see no hook).
inline StepMonitor* installed_step_monitor = nullptr;

/// Tells the installed monitor, if any, that `sim` stopped stepping.
inline void notify_run_ended(const Simulation& sim) {
  if (installed_step_monitor != nullptr) installed_step_monitor->run_ended(sim);
}

/// Installs a monitor for the lifetime of this object and restores the previous one after it.
class ScopedStepMonitor {
 public:
  explicit ScopedStepMonitor(StepMonitor& monitor) : previous_(installed_step_monitor) {
    installed_step_monitor = &monitor;
  }
  ~ScopedStepMonitor() { installed_step_monitor = previous_; }
  ScopedStepMonitor(const ScopedStepMonitor&) = delete;
  ScopedStepMonitor& operator=(const ScopedStepMonitor&) = delete;

 private:
  StepMonitor* previous_;
};

}  // namespace bpm
