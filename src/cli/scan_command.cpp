#include <algorithm>
#include <cstdio>

#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/scan_job.hpp"

namespace occlusion::cli {

namespace {

void print_human(const ScanReport& report) {
  const ScanResult& r = report.result;
  std::printf("fixed-viewpoint scan of %s\n", report.request.path.c_str());
  std::printf("  visible fraction  %.4f   (%zu of %zu points)\n", r.visible_fraction,
              r.visible_points, r.visible_count.size());
  print_viewpoints_and_filter(report.viewpoint_source, report.station_filter);
  const double points = static_cast<double>(std::max<std::size_t>(r.visible_count.size(), 1));
  for (std::size_t v = 0; v < report.viewpoint_positions.size(); ++v) {
    const auto& p = report.viewpoint_positions[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  sees %zu points (%.4f), only it %zu (%.4f)\n",
                report.viewpoint_names[v].c_str(), p.x(), p.y(), p.z(), r.seen_by_viewpoint[v],
                static_cast<double>(r.seen_by_viewpoint[v]) / points, r.only_by_viewpoint[v],
                static_cast<double>(r.only_by_viewpoint[v]) / points);
  }
  const std::size_t unseen = r.visible_count.size() - r.visible_points;
  std::printf("  seen by several   %.4f   (%zu points); by none %.4f   (%zu points)\n",
              static_cast<double>(r.seen_by_several) / points, r.seen_by_several,
              static_cast<double>(unseen) / points, unseen);
  if (!report.classes.empty()) {
    std::printf("  classes:%*s points   visible\n", 16, "");
    for (const auto& c : report.classes) {
      if (c.points == 0) continue;
      std::printf("    %-20s %9zu   %.4f\n", c.name.c_str(), c.points, c.visible_fraction);
    }
  }
  std::printf("  time: load %.3f s, octree %.3f s, tracing %.3f s, total %.3f s\n",
              report.load_seconds, r.build_seconds, r.trace_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_scan(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<ScanReport>());
}

}  // namespace occlusion::cli
