#pragma once
// Timing, formatting and CLI-running helpers of the bench tools (bench_moc,
// bench_poc), so that both report figures measured the same way.

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <filesystem>
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

// The seconds run() takes.
template <class F>
double timed(F&& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return seconds_since(start);
}

// The smallest of kRepetitions results of run() (seconds).
template <class F>
double best_of(F&& run) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kRepetitions; ++k) best = std::min(best, run());
  return best;
}

// Timings of one measurement repeated: the smallest and the median.
struct Samples {
  std::vector<double> seconds;

  double min() const {
    return seconds.empty() ? std::numeric_limits<double>::infinity()
                           : *std::min_element(seconds.begin(), seconds.end());
  }
  double median() const {
    if (seconds.empty()) return std::numeric_limits<double>::infinity();
    std::vector<double> sorted = seconds;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  }
};

// `repetitions` results each of ours() and of theirs() (seconds), run in turn
// (ours, theirs, ours, ...), so that a busy machine slows both alike and the
// ratio of the two minima (or medians) holds when the absolute figures drift.
template <class F, class G>
std::pair<Samples, Samples> alternating_samples(int repetitions, F&& ours, G&& theirs) {
  std::pair<Samples, Samples> samples;
  for (int k = 0; k < repetitions; ++k) {
    samples.first.seconds.push_back(ours());
    samples.second.seconds.push_back(theirs());
  }
  return samples;
}

// The smallest of `repetitions` results of ours() and of theirs(), run in turn
// as above.
template <class F, class G>
std::pair<double, double> best_of_alternating(int repetitions, F&& ours, G&& theirs) {
  const auto [a, b] = alternating_samples(repetitions, ours, theirs);
  return {a.min(), b.min()};
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

// The best wall times of `repetitions` runs each of two programs, run in turn
// (first, second, first, ...) so that a busy machine slows both alike; see
// child_process.hpp for the peak RSS, and call this while the caller is small.
// A failed run ends that program's series and is returned as it is. Each
// JSON is that program's best run's stdout, parsed; null if it is not JSON.
inline std::pair<CliRun, CliRun> run_clis_alternating(const std::vector<std::string>& first,
                                                      const std::string& first_capture,
                                                      const std::vector<std::string>& second,
                                                      const std::string& second_capture,
                                                      int repetitions = kRepetitions) {
  std::pair<CliRun, CliRun> runs;
  std::pair<bool, bool> failed(false, false);
  runs.first.best.wall_seconds = std::numeric_limits<double>::infinity();
  runs.second.best.wall_seconds = std::numeric_limits<double>::infinity();
  const auto one = [](const std::vector<std::string>& argv, const std::string& capture, CliRun& run,
                      bool& failed_before) {
    if (failed_before) return;
    ChildResult r = run_measured(argv, capture);
    failed_before = r.exit_code != 0;
    if (failed_before || r.wall_seconds < run.best.wall_seconds) run.best = std::move(r);
  };
  for (int k = 0; k < repetitions; ++k) {
    one(first, first_capture, runs.first, failed.first);
    if (!second.empty()) one(second, second_capture, runs.second, failed.second);
  }
  for (CliRun* run : {&runs.first, &runs.second}) {
    std::istringstream in(run->best.out);
    std::string errors;
    if (!Json::parseFromStream(Json::CharReaderBuilder(), in, &run->json, &errors)) {
      run->json = Json::Value();
    }
  }
  return runs;
}

// The best wall time of kRepetitions runs of argv, as above.
inline CliRun run_cli(const std::vector<std::string>& argv, const std::string& capture_prefix) {
  return run_clis_alternating(argv, capture_prefix, {}, {}).first;
}

// `cli -JOB INPUT --json --out DIR/ours SETTINGS` and `embree_job -JOB INPUT
// --out DIR/embree SETTINGS` (embree_job.cpp: the same job on Embree), in turn
// as above; DIR is bench_JOB_out and the captures bench_JOB_cli and
// bench_JOB_embree_job, all in bench_dir, where embree_job is too.
inline std::pair<CliRun, CliRun> run_job_and_embree_job(
    const std::filesystem::path& bench_dir, const std::string& cli, const std::string& job,
    const std::string& input, const std::vector<std::string>& settings, int repetitions) {
  const std::string name = "bench_" + job;
  const std::string out = (bench_dir / (name + "_out")).string();
  std::vector<std::string> ours = {cli, "-" + job, input, "--json", "--out", out + "/ours"};
  std::vector<std::string> theirs = {(bench_dir / "embree_job").string(), "-" + job, input, "--out",
                                     out + "/embree"};
  ours.insert(ours.end(), settings.begin(), settings.end());
  theirs.insert(theirs.end(), settings.begin(), settings.end());
  return run_clis_alternating(ours, (bench_dir / (name + "_cli")).string(), theirs,
                              (bench_dir / (name + "_embree_job")).string(), repetitions);
}

// "load 0.050, build 0.400, trace 0.900, total 1.400 s": the stages a job's
// JSON timings hold, in the order they run.
inline std::string stage_timings(const Json::Value& json) {
  std::string text;
  const Json::Value& timings = json["timings"];
  for (const char* stage : {"load", "sampling", "surfel", "build", "trace", "write", "total"}) {
    const std::string key = std::string(stage) + "_seconds";
    if (!timings.isMember(key)) continue;
    char figure[48];
    std::snprintf(figure, sizeof figure, "%s%s %.3f", text.empty() ? "" : ", ", stage,
                  timings[key].asDouble());
    text += figure;
  }
  return text.empty() ? "no timings" : text + " s";
}

// Two lines, ours and the Embree program's whole process (wall from fork to
// exit, peak RSS, their own stage timings), then the ratio of the wall times
// (goal >= 1.0, issue 17). False if either failed.
inline bool print_whole_process(const char* job, const CliRun& ours, const CliRun& embree) {
  bool ok = true;
  for (const auto& [who, run] : {std::pair<const char*, const CliRun*>("ours  ", &ours),
                                 std::pair<const char*, const CliRun*>("embree", &embree)}) {
    const ChildResult& c = run->best;
    if (c.exit_code != 0) {
      std::printf("%s whole process, %s: FAILED (exit %d)\n%s", job, who, c.exit_code,
                  c.err.c_str());
      ok = false;
      continue;
    }
    std::printf("%s whole process, %s %.3f s, peak RSS %.0f MB (%s)\n", job, who, c.wall_seconds,
                static_cast<double>(c.peak_rss_bytes) / 1e6, stage_timings(run->json).c_str());
  }
  if (ok) {
    std::printf("%s whole-process ours/embree speed: %.2f\n", job,
                embree.best.wall_seconds / ours.best.wall_seconds);
  }
  return ok;
}

}  // namespace occlusion::bench
