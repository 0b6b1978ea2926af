#include <cstdio>

#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/region_growing_job.hpp"

namespace occlusion::cli {

namespace {

void print_human(const RegionGrowingReport& report) {
  const MeshEstimate& e = report.estimate;
  const MeshOcclusionResult& r = report.occlusion;
  std::printf("region-growing occlusion of %s\n", report.request.path.c_str());
  std::printf("  occlusion level  %.4f   (visible area %.4g of %.4g)\n", r.occlusion_level,
              r.visible_area, r.total_area);
  std::printf("  points %zu, clusters found %zu, used %zu, skipped %zu\n", report.points,
              e.clusters_found, e.clusters_used, e.skipped.size());
  std::printf("  planes cover %.1f %% of the points (%zu edge points recovered)\n",
              100.0 * e.covered_fraction, e.edge_points);
  std::printf("  mesh: %zu faces, %zu samples, %zu rays\n", r.faces, r.samples, r.rays);
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    const auto& vp = r.viewpoints[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  sees %.4f of the area\n",
                report.viewpoint_names[v].c_str(), vp.position.x(), vp.position.y(),
                vp.position.z(), vp.visible_fraction);
  }
  std::printf(
      "  time: load %.3f s, normals %.3f s, region growing %.3f s, planes %.3f s, hulls %.3f s,\n"
      "        occlusion %.3f s, total %.3f s\n",
      report.load_seconds, e.timings.normals_seconds, e.timings.region_growing_seconds,
      e.timings.planes_seconds, e.timings.hulls_seconds,
      r.timings.sampling_seconds + r.timings.build_seconds + r.timings.trace_seconds,
      report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_region_growing(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<RegionGrowingReport>());
}

}  // namespace occlusion::cli
