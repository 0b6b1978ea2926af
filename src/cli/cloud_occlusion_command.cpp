#include <cstdio>

#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/job_registry.hpp"

namespace occlusion::cli {

namespace {

void print_human(const CloudOcclusionReport& report) {
  const CloudOcclusionResult& r = report.result;
  std::printf("point-cloud occlusion of %s (%zu points, %zu openings)\n",
              report.request.path.c_str(), r.points, report.openings);
  // The level with the counts that make it (level_counts.hpp): a reader can add it up.
  std::printf("  occlusion level  %s\n",
              level_counts_text(ray_counts(r), report.outside_view_why).c_str());
  print_viewpoints_and_filter(report.viewpoint_source, report.station_filter);
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    const auto& vp = r.viewpoints[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  occlusion %.4f = %zu / %zu rays%s\n",
                report.viewpoint_names[v].c_str(), vp.position.x(), vp.position.y(),
                vp.position.z(), vp.occlusion_level, vp.occlusion_rays,
                ray_counts(vp).rays_in_view(), vp.outside_view_rays > 0 ? " inside the view" : "");
  }
  if (report.exterior) {
    std::printf(
        "  exterior structure only: occlusion level %s; interior/exterior points "
        "%zu/%zu = %.4f\n",
        level_counts_text(ray_counts(report.exterior->result), report.outside_view_why).c_str(),
        report.exterior->interior_points, report.exterior->exterior_points,
        report.exterior->interior_exterior_ratio);
  }
  if (report.dropped_nan > 0) std::printf("  dropped %zu NaN points\n", report.dropped_nan);
  std::printf("  time: load %.3f s, octree %.3f s, tracing %.3f s, total %.3f s\n",
              report.load_seconds, r.build_seconds, r.trace_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_cloud_occlusion(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<CloudOcclusionReport>());
}

}  // namespace occlusion::cli
