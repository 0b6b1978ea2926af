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
#include "occlusion/app/key.hpp"
#include "occlusion/app/viewpoint_choice.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct RegionGrowingRequest {
  std::string path;  // point cloud: PCD, PLY, text or an S3DIS folder
  ViewpointChoice viewpoints = ViewpointChoice::from_pattern(7);
  RegionGrowingOptions estimation;  // its `threads` is replaced by `threads` below
  // The mesh occlusion of the estimated mesh, as -moc.
  double samples_per_unit_area = 100.0;
  // The density is raised until the mesh gets at least this many samples
  // (mesh_sampling.hpp: density_for_min_samples), so a small scene is not
  // measured with one sample per face. 10,000 samples put the standard error
  // of a visible fraction below 0.5 % (sqrt(p (1 - p) / n) <= 0.5 / 100).
  // 0 keeps samples_per_unit_area as given.
  std::size_t min_samples = 10000;
  double octree_resolution = 0.0;
  bool enable_acceleration = true;
  std::uint64_t seed = 0;
  unsigned threads = 0;  // 0 = all cores
  bool skip_bad_lines = false;
  std::string out;  // directory for output files; empty = none
  // Refuse, before the work, a request estimated to need more (memory_budget.hpp); 0 = the machine.
  std::uint64_t max_memory_mb = 0;
  // Refuse, before the work, a request estimated to trace more (work_budget.hpp),
  // in G ray steps; 0 = no budget.
  double max_work = 0;
};

struct RegionGrowingReport {
  RegionGrowingRequest request;
  double samples_per_unit_area = 0.0;  // the density used (request's, or raised to min_samples)
  MeshEstimate estimate;
  MeshOcclusionResult occlusion;
  std::vector<std::string> viewpoint_names;
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
