#include "progress_printer.hpp"

#include <cstdio>
#include <memory>

namespace occlusion::cli {

Progress make_progress_printer(const std::string& job, bool quiet) {
  Progress progress;
  if (quiet) return progress;
  struct State {
    std::string stage;
    int tenth = -1;
  };
  auto state = std::make_shared<State>();
  progress.report = [job, state](const std::string& stage, double fraction) {
    const int tenth = static_cast<int>(fraction * 10.0);
    if (stage == state->stage && tenth <= state->tenth) return;
    state->stage = stage;
    state->tenth = tenth;
    std::fprintf(stderr, "[%s] %s %3.0f%%\n", job.c_str(), stage.c_str(), fraction * 100.0);
  };
  return progress;
}

}  // namespace occlusion::cli
