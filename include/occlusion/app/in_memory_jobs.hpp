#pragma once
// The jobs on data already in memory (the Python module's numpy arrays): what
// run_scan, run_cloud_occlusion and run_mesh_occlusion compute once their
// input is loaded, viewpoints placed on its bounding box as those place them,
// openings read from request.polygon_path; scans, min_range and max_range
// filter a copy (per-point results are then of the points kept). request.path only names the data
// in messages and reports. Nothing is written: UsageError when request.out is set.

#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

ScanReport scan_in_memory(const PointCloud& cloud, const ScanRequest& request,
                          const Progress& progress = {});
CloudOcclusionReport cloud_occlusion_in_memory(const PointCloud& cloud,
                                               const CloudOcclusionRequest& request,
                                               const Progress& progress = {});
MeshOcclusionReport mesh_occlusion_in_memory(const TriangleMesh& mesh,
                                             const MeshOcclusionRequest& request,
                                             const Progress& progress = {});

}  // namespace occlusion
