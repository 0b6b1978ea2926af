#pragma once
// The `extract_polygons` job: the planes region growing finds in a point
// cloud, as polygons (a mesh of triangle fans, one group per cluster), and
// every point's cluster, without measuring occlusion: what the viewer shows
// to check the segmentation, or to pick openings, before -rgoc. It reads the
// `occlusion.region_growing` section; that section's occlusion keys
// (viewpoints, samples_per_unit_area, ...) do not apply and are ignored.

#include <json/value.h>

#include <string>
#include <vector>

#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct ExtractPolygonsRequest {
  std::string path;                 // point cloud: PCD, PLY, text or an S3DIS folder
  RegionGrowingOptions estimation;  // its `threads` is replaced by `threads` below
  unsigned threads = 0;             // 0 = all cores
  bool skip_bad_lines = false;
  std::string out;  // directory for output files; empty = none
  // Refuse, before the work, a request estimated to need more (memory_budget.hpp); 0 = the machine.
  std::uint64_t max_memory_mb = 0;
};

struct ExtractPolygonsReport {
  ExtractPolygonsRequest request;
  MeshEstimate estimate;
  // The cloud's global shift (PointCloud::shift); the estimate and the
  // viewpoints are in the file's frame.
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  std::size_t points = 0;  // as loaded
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0;
  double total_seconds = 0.0;
};

void validate(const ExtractPolygonsRequest& request);
// Every key of the job (config section occlusion.extract_polygons), declared once.
const Keys<ExtractPolygonsRequest>& extract_polygons_keys();
// With `out`: CLOUD.polygons.obj, CLOUD.segmented.ply (an int `cluster` per
// point) and CLOUD.polygons.json. Errors as run_region_growing_occlusion's.
ExtractPolygonsReport run_extract_polygons(const ExtractPolygonsRequest& request,
                                           const Progress& progress = {});
// Headline: clusters_used (the planes that became polygons).
Json::Value to_json(const ExtractPolygonsReport& report);

}  // namespace occlusion
