#include <cstdio>

#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/reconstruct_job.hpp"

namespace occlusion::cli {

namespace {

void print_human(const ReconstructReport& report) {
  std::printf("reconstructed %s: %zu points in %zu room(s)\n", report.request.path.c_str(),
              report.points, report.rooms.size());
  for (const auto& c : report.classes) {
    if (c.points == 0) continue;
    std::printf("  %-10s %9zu points  %4zu instances\n", c.name.c_str(), c.points, c.instances);
  }
  if (report.skipped_lines > 0) std::printf("  skipped %zu bad lines\n", report.skipped_lines);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_reconstruct(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<ReconstructReport>());
}

}  // namespace occlusion::cli
