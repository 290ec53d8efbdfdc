#pragma once
/// The progress line (scenario/run_progress.hpp) on stderr for the DEM runs a command makes while
/// this object lives; nothing under --quiet. The line is cleared when it goes, before the result
/// lines.
#include <cstdio>
#include <optional>

#include "cli/global_options.hpp"
#include "io/log.hpp"
#include "scenario/run_progress.hpp"

namespace bpm::cli {

class DemProgress {
 public:
  explicit DemProgress(const ProgressPlan& plan) {
    if (!progress_enabled()) return;
    progress_.emplace(plan, stderr, RunProgress::settings_for(stderr, log::shows_detail()));
    watching_.emplace(*progress_);
  }

 private:
  std::optional<RunProgress> progress_;
  std::optional<ScopedStepMonitor>
      watching_;  // destroyed first: uninstalled before the reporter goes
};

}  // namespace bpm::cli
