#pragma once
// The `region_growing_occlusion` job (-rgoc): estimate a mesh from a point
// cloud by region growing (analysis/mesh_estimation.hpp), then measure that
// mesh's occlusion exactly as -moc does, from viewpoints placed on the
// cloud's bounding box.

#include <json/value.h>

#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/progress.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/app/viewpoint_choice.hpp"

namespace occlusion {

struct RegionGrowingRequest {
  std::string path;  // point cloud: PCD, PLY, text or an S3DIS folder
  ViewpointChoice viewpoints = ViewpointChoice::from_pattern(7);
  RegionGrowingOptions estimation;  // its `threads` is replaced by `threads` below
  // The mesh occlusion of the estimated mesh, as -moc.
  double samples_per_unit_area = 100.0;
  double octree_resolution = 0.0;
  bool enable_acceleration = true;
  std::uint64_t seed = 0;
  unsigned threads = 0;  // 0 = all cores
  bool skip_bad_lines = false;
  std::string out;  // directory for output files; empty = none
};

struct RegionGrowingReport {
  RegionGrowingRequest request;
  MeshEstimate estimate;
  MeshOcclusionResult occlusion;
  std::vector<std::string> viewpoint_names;
  std::size_t points = 0;  // as loaded
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0;
  double total_seconds = 0.0;
};

// Throws UsageError naming the offending option.
void validate(const RegionGrowingRequest& request);

// Every key of the job (config section occlusion.region_growing), declared once.
const Keys<RegionGrowingRequest>& region_growing_keys();
// The region-growing keys alone (also -rgoc's, extract_polygons' and the study's).
const Keys<RegionGrowingOptions>& estimation_keys();

// Loads the cloud, estimates the mesh, computes its occlusion, writes outputs.
// A cloud in which no cluster becomes a plane is a UsageError whose message
// names the option to change. Throws UsageError, InputError, OutputError, Cancelled.
RegionGrowingReport run_region_growing_occlusion(const RegionGrowingRequest& request,
                                                 const Progress& progress = {});

// The report as one JSON object with the headline figure `occlusion_level`.
Json::Value to_json(const RegionGrowingReport& report);

}  // namespace occlusion
