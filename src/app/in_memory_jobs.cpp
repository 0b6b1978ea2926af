#include "occlusion/app/in_memory_jobs.hpp"

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"

namespace occlusion {

namespace {

// Output files are named after an input file; data in memory has none.
void refuse_out(const std::string& out) {
  if (!out.empty()) {
    throw UsageError(
        "'out': data given in memory writes no files; write it with write_cloud "
        "or write_obj and pass the path");
  }
}

// The cloud as the filter leaves it: itself when the filter is off, else
// the filtered `copy` (the caller's arrays stay as they are).
const PointCloud& filter_in_memory(const PointCloud& cloud, const StationFilter& filter,
                                   const std::string& name, PointCloud& copy,
                                   StationFilterReport& dropped) {
  dropped.filter = filter;
  if (!filter.active()) return cloud;
  copy = cloud;
  dropped = apply_station_filter(copy, filter, name);
  return copy;
}

}  // namespace

ScanReport scan_in_memory(const PointCloud& cloud, const ScanRequest& request,
                          const Progress& progress) {
  refuse_out(request.out);
  cloud.validate();
  PointCloud copy;
  StationFilterReport dropped;
  const PointCloud& filtered =
      filter_in_memory(cloud, station_filter(request), request.path, copy, dropped);
  ScanReport report = run_scan_on(
      filtered, job::resolve_for_cloud(request.viewpoints, filtered, request.frame, request.up),
      request, progress);
  report.station_filter = dropped;
  return report;
}

CloudOcclusionReport cloud_occlusion_in_memory(const PointCloud& cloud,
                                               const CloudOcclusionRequest& request,
                                               const Progress& progress) {
  refuse_out(request.out);
  cloud.validate();
  PointCloud copy;
  StationFilterReport dropped;
  const PointCloud& filtered =
      filter_in_memory(cloud, station_filter(request), request.path, copy, dropped);
  CloudOcclusionReport report = run_cloud_occlusion_on(
      filtered, job::resolve_for_cloud(request.viewpoints, filtered, request.frame, request.up),
      read_openings(request.polygon_path), request, progress);
  report.station_filter = dropped;
  return report;
}

MeshOcclusionReport mesh_occlusion_in_memory(const TriangleMesh& mesh,
                                             const MeshOcclusionRequest& request,
                                             const Progress& progress) {
  refuse_out(request.out);
  mesh.validate();
  return run_mesh_occlusion_on(mesh, request, progress);
}

}  // namespace occlusion
