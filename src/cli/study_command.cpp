#include <cstdio>
#include <string>

#include "commands.hpp"
#include "common_options.hpp"
#include "interrupt.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/study_job.hpp"

namespace occlusion::cli {

namespace {

std::string figure(const std::optional<double>& value) {
  return optional_figure(value, "%+.3f", "     -");
}

void print_human(const StudyReport& report) {
  if (report.job == "study") {
    std::printf(
        "occlusion study: %zu runs made, %zu already in study.csv (shard %s of %zu runs), %zu "
        "failed\n",
        report.runs_computed, report.runs_skipped, report.request.shard.c_str(), report.runs_total,
        report.runs_failed);
  } else {
    std::printf("occlusion study: %zu runs merged from %zu CSV files\n", report.table.rows.size(),
                report.inputs.size());
  }
  std::printf("  correlation with mIoU over %zu runs:\n", report.table.rows.size());
  for (const auto& m : report.correlations) {
    std::printf("    %-26s n %3zu   Pearson %s   Spearman %s\n", m.measure.c_str(), m.correlation.n,
                figure(m.correlation.pearson).c_str(), figure(m.correlation.spearman).c_str());
  }
  std::printf("  time %.3f s\n", report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

// The study goes on past a failed run, but must not look like a success.
int failed_status(std::size_t failed) {
  if (failed == 0) return 0;
  std::fprintf(stderr, "occlusion: %zu runs failed (status 'failed' in study.csv)\n", failed);
  return 1;
}

}  // namespace

void print_study(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<StudyReport>());
}

int run_study_merge_command(const std::vector<std::string>& args) {
  bool json = false;
  std::vector<std::string> positional, compare_with;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--json") {
      json = true;
    } else if (arg == "--compare-with") {
      if (i + 1 == args.size()) throw UsageError("--compare-with needs a study's folder");
      compare_with.push_back(args[++i]);
    } else if (arg == "-h" || arg == "--help") {
      std::printf(
          "usage: occlusion study merge OUT A.csv [B.csv ...] [--compare-with DIR ...] "
          "[--json] [-q]\n\n"
          "Joins the study.csv tables of shards (--shard I/N) into OUT: the table and the\n"
          "statistics are those of one unsharded run. --compare-with: another study's\n"
          "folder of the same runs, whose slopes study.md sets beside these (the study's\n"
          "compare_with key).\n");
      return 0;
    } else if (arg == "-q" || arg == "--quiet") {
      // merging prints no progress
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "' for study merge");
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() < 2) throw UsageError("usage: occlusion study merge OUT A.csv [B.csv ...]");
  const StudyReport report =
      run_study_merge({positional.begin() + 1, positional.end()}, positional.front(), compare_with);
  print_warnings(report.warnings);
  if (json) {
    print_json(to_json(report));
  } else {
    print_human(report);
  }
  return failed_status(report.runs_failed);
}

int study_exit_status(const JobRun& run) {
  return failed_status(run.report_as<StudyReport>().runs_failed);
}

}  // namespace occlusion::cli
