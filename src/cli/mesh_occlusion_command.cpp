#include <cstdio>

#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"

namespace occlusion::cli {

namespace {

void print_human(const MeshOcclusionReport& report) {
  const MeshOcclusionResult& r = report.result;
  std::printf("mesh occlusion of %s\n", report.request.path.c_str());
  std::printf("  occlusion level  %.4f   (visible area %.4g of %.4g)\n", r.occlusion_level,
              r.visible_area, r.total_area);
  std::printf("  faces %zu, samples %zu, rays %zu\n", r.faces, r.samples, r.rays);
  std::printf("  viewpoints:\n");
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    const auto& vp = r.viewpoints[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  sees %.4f of the area\n",
                report.viewpoint_names[v].c_str(), vp.position.x(), vp.position.y(),
                vp.position.z(), vp.visible_fraction);
  }
  if (r.groups.size() > 1) {
    std::printf("  groups:%*s faces        area  occlusion\n", 22, "");
    for (const auto& g : r.groups) {
      std::printf("    %-24s %7zu %11.4g  %9.4f\n", g.name.c_str(), g.faces, g.total_area,
                  g.occlusion_level);
    }
  }
  std::printf("  time: load %.3f s, sampling %.3f s, octree %.3f s, tracing %.3f s, total %.3f s\n",
              report.load_seconds, r.timings.sampling_seconds, r.timings.build_seconds,
              r.timings.trace_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_mesh_occlusion(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<MeshOcclusionReport>());
}

}  // namespace occlusion::cli
