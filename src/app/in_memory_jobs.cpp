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

}  // namespace

ScanReport scan_in_memory(const PointCloud& cloud, const ScanRequest& request,
                          const Progress& progress) {
  refuse_out(request.out);
  cloud.validate();
  return run_scan_on(cloud, job::resolve_for_cloud(request.viewpoints, cloud), request, progress);
}

CloudOcclusionReport cloud_occlusion_in_memory(const PointCloud& cloud,
                                               const CloudOcclusionRequest& request,
                                               const Progress& progress) {
  refuse_out(request.out);
  cloud.validate();
  return run_cloud_occlusion_on(cloud, job::resolve_for_cloud(request.viewpoints, cloud),
                                read_openings(request.polygon_path), request, progress);
}

MeshOcclusionReport mesh_occlusion_in_memory(const TriangleMesh& mesh,
                                             const MeshOcclusionRequest& request,
                                             const Progress& progress) {
  refuse_out(request.out);
  mesh.validate();
  return run_mesh_occlusion_on(mesh, request, progress);
}

}  // namespace occlusion
