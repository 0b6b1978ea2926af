#pragma once
// What every command does once its options are parsed: --help, or run the job
// with progress on stderr, print its warnings, then one JSON object or the
// human summary on stdout.

#include <functional>

#include "common_options.hpp"
#include "interrupt.hpp"
#include "progress_printer.hpp"

namespace occlusion::cli {

template <class Report>
int run_command(const OutputOptions& output, const std::string& job,
                const std::function<void()>& print_help,
                const std::function<Report(const Progress&)>& run,
                const std::function<void(const Report&)>& print_human) {
  if (output.help) {
    print_help();
    return 0;
  }
  Progress progress = make_progress_printer(job, output.quiet);
  progress.cancel = &interrupt_flag();
  const Report report = run(progress);
  print_warnings(report.warnings);
  if (output.json) {
    print_json(to_json(report));
  } else {
    print_human(report);
  }
  return 0;
}

}  // namespace occlusion::cli
