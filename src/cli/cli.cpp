// The command line's dispatch: `occlusion --help`, and each job of the
// registry by its command-line names.

#include "occlusion/cli/cli.hpp"

#include <cstdio>

#include "commands.hpp"
#include "interrupt.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion::cli {

namespace {

void print_help() {
  std::printf(
      "usage: occlusion COMMAND INPUT [options]\n"
      "\n"
      "How occluded is an indoor scene, seen from given viewpoints?\n"
      "\n"
      "commands:\n");
  for (const auto& job : jobs()) {
    std::string names;
    for (const auto& name : job.cli_names) names += (names.empty() ? "" : ", ") + name;
    std::printf("  %-34s %s\n", names.c_str(), job.summary.c_str());
  }
  std::printf(
      "  %-34s %s\n"
      "  %-34s %s\n"
      "  %-34s %s\n"
      "\n"
      "Run 'occlusion COMMAND --help' for a command's options.\n"
      "Exit codes: 0 success, 1 failure, 2 usage or configuration error, 3 input file error.\n",
      "study merge OUT A.csv B.csv ...", "join the tables of study shards", "serve",
      "the browser viewer and its WebSocket server", "keys",
      "every option and config key, as Markdown (docs/options.md)");
}

}  // namespace

int run_command_line(const std::vector<std::string>& args);

int run(const std::vector<std::string>& args) {
  try {
    return run_command_line(args);
  } catch (const Cancelled&) {
    // The job unwound and removed its temporary files: say so, then die of
    // the signal that asked for it, as a signalled process should.
    std::fprintf(stderr, "occlusion: cancelled\n");
    reraise_interrupt();
    return exit_code(ErrorKind::kCancelled);
  }
}

int run_command_line(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    print_help();
    return args.empty() ? exit_code(ErrorKind::kUsage) : 0;
  }
  if (args[0] == "keys") {
    std::printf("%s", keys_markdown().c_str());
    return 0;
  }
  if (args[0] == "--version") {
    std::printf("occlusion 0.1.0\n");
    return 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "study" && !rest.empty() && rest.front() == "merge") {
    return run_study_merge_command({rest.begin() + 1, rest.end()});
  }
  for (const auto& job : jobs()) {
    for (const auto& name : job.cli_names) {
      if (name == args[0]) return run_job_command(job, rest);
    }
  }
  throw UsageError("unknown command '" + args[0] + "' (see occlusion --help)");
}

int exit_code(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kUsage:
      return 2;
    case ErrorKind::kInput:
      return 3;
    case ErrorKind::kOutput:
    case ErrorKind::kCancelled:
    case ErrorKind::kResource:
    case ErrorKind::kInternal:
      break;
  }
  return 1;
}

}  // namespace occlusion::cli
