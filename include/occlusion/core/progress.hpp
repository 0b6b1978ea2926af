#pragma once
// Progress reporting and cancellation for long analyses. The app layer turns
// these into stderr lines (CLI) or rate-limited events (server). It lives in
// core so that every layer, readers included, can report progress and be cancelled.

#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>

namespace occlusion {

struct Progress {
  // Called from the thread that runs the analysis, with fraction in [0, 1].
  std::function<void(const std::string& stage, double fraction)> report;
  // When set and true, the analysis stops at the next block and throws Cancelled.
  const std::atomic<bool>* cancel = nullptr;

  void operator()(const std::string& stage, double fraction) const {
    if (report) report(stage, fraction);
  }
  // Throws Cancelled if cancellation was requested.
  void check_cancel() const;
};

struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace occlusion
