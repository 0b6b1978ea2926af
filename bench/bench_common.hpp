#pragma once
// Timing, formatting and CLI-running helpers of the bench tools (bench_moc,
// bench_poc), so that both report figures measured the same way.

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <json/json.h>

#include "child_process.hpp"

namespace occlusion::bench {

inline constexpr int kRepetitions = 3;

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The smallest of kRepetitions results of run() (seconds).
template <class F>
double best_of(F&& run) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kRepetitions; ++k) best = std::min(best, run());
  return best;
}

// The smallest of `repetitions` results of ours() and of theirs(), run in
// turn (ours, theirs, ours, ...), so that a busy machine slows both alike and
// the ratio of the two minima holds when the absolute figures drift.
template <class F, class G>
std::pair<double, double> best_of_alternating(int repetitions, F&& ours, G&& theirs) {
  std::pair<double, double> best(std::numeric_limits<double>::infinity(),
                                 std::numeric_limits<double>::infinity());
  for (int k = 0; k < repetitions; ++k) {
    best.first = std::min(best.first, ours());
    best.second = std::min(best.second, theirs());
  }
  return best;
}

// 1234567 -> "1,234,567"
inline std::string grouped(std::size_t n) {
  std::string digits = std::to_string(n);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(at, ",");
  return digits;
}

// The shortest text that reads back as `value`, for passing numbers to the CLI.
inline std::string exact(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

inline double mib(std::size_t bytes) {
  return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

struct CliRun {
  ChildResult best;
  Json::Value json;  // the best run's stdout parsed as JSON; null if it is not JSON
};

// The best wall time of kRepetitions runs of argv (see child_process.hpp for
// the peak RSS, and call this while the caller is small); a failed run ends
// the series and is returned as it is.
inline CliRun run_cli(const std::vector<std::string>& argv, const std::string& capture_prefix) {
  CliRun run;
  run.best.wall_seconds = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kRepetitions; ++k) {
    ChildResult r = run_measured(argv, capture_prefix);
    if (r.exit_code != 0) {
      run.best = std::move(r);
      return run;
    }
    if (r.wall_seconds < run.best.wall_seconds) run.best = std::move(r);
  }
  std::istringstream in(run.best.out);
  std::string errors;
  if (!Json::parseFromStream(Json::CharReaderBuilder(), in, &run.json, &errors)) {
    run.json = Json::Value();
  }
  return run;
}

}  // namespace occlusion::bench
