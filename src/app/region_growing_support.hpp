#pragma once
// The region-growing estimate as two jobs use it (internal to app/): -rgoc,
// which goes on to measure the mesh's occlusion, and extract_polygons, which
// stops at the planes. Options, checks, warnings and JSON live here once.

#include <json/value.h>

#include <string>
#include <vector>

#include "job_support.hpp"
#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion::job {

// The declared ranges and max_cluster_size >= min_cluster_size. Throws KeyError.
void validate_estimation(const RegionGrowingOptions& options);

// The cloud loaded and its planes estimated: where both jobs start.
struct CloudEstimate {
  LoadedCloud loaded;
  double load_seconds = 0.0;
  MeshEstimate estimate;
  // What the user should know without reading the JSON: PCL dropping whole
  // surfaces for their size, and clusters that gave no polygon.
  std::vector<std::string> warnings;
};

// Throws what load_cloud throws; InputError for fewer than 3 points;
// UsageError (naming the option to change) when no cluster gives a plane.
// `threads` replaces options.threads.
// Refused (UsageError) before estimating when region_growing_memory exceeds
// max_memory_mb (0: no budget).
CloudEstimate load_and_estimate(const std::string& path, bool skip_bad_lines,
                                RegionGrowingOptions options, unsigned threads,
                                std::uint64_t max_memory_mb, const Progress& progress);

// Moves the estimate, the counts and the warnings into a job's report.
template <class Report>
void take_estimate(CloudEstimate& input, Report& report) {
  report.points = input.loaded.cloud.size();
  report.dropped_nan = input.loaded.dropped_nan;
  report.skipped_lines = input.loaded.skipped_lines;
  report.load_seconds = input.load_seconds;
  report.estimate = std::move(input.estimate);
  report.warnings = std::move(input.warnings);
}

// The estimate (made in the cloud's local frame, PointCloud::shift) moved to
// the file's frame: mesh vertices, plane centroids and offsets.
void estimate_to_original(MeshEstimate& estimate, const Eigen::Vector3d& shift);
// Every point's cluster as an integer field (-1: none), for the segmented cloud.
ScalarField cluster_field(const MeshEstimate& estimate);

// The estimate's counts, regions and skipped clusters, added to `json`.
void add_estimation_json(const MeshEstimate& estimate, Json::Value& json);
// One plane, without figures of its occlusion.
Json::Value plane_json(const EstimatedPlane& plane);
// The estimate's stage timings, added to `timings`.
void add_estimation_timings(const MeshEstimate& estimate, Json::Value& timings);

}  // namespace occlusion::job
