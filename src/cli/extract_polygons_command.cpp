#include <cstdio>

#include "commands.hpp"
#include "occlusion/app/extract_polygons_job.hpp"

namespace occlusion::cli {

void print_extract_polygons(const JobRun& run, const FaceOptions&) {
  const auto& report = run.report_as<ExtractPolygonsReport>();
  const MeshEstimate& e = report.estimate;
  std::printf("planes of %s (%zu points)\n", report.request.path.c_str(), report.points);
  std::printf("  %zu of %zu clusters became polygons (%zu triangles)\n", e.clusters_used,
              e.clusters_found, e.mesh.face_count());
  std::printf("  time: load %.3f s, total %.3f s\n", report.load_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace occlusion::cli
