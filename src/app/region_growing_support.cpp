#include "region_growing_support.hpp"

#include <map>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::job {

namespace {

// What the user should know without reading the JSON: PCL dropping whole
// surfaces for their size, and clusters that gave no polygon.
std::vector<std::string> estimation_warnings(const MeshEstimate& estimate,
                                             const RegionGrowingOptions& options) {
  std::vector<std::string> warnings;
  if (estimate.regions.too_large > 0) {
    warnings.push_back(std::to_string(estimate.regions.too_large) + " regions (" +
                       std::to_string(estimate.regions.too_large_points) +
                       " points) are larger than max_cluster_size " +
                       std::to_string(options.max_cluster_size) +
                       " and were left out: raise --max-cluster-size to keep them");
  }
  if (!estimate.skipped.empty()) {
    std::map<std::string, std::size_t> reasons;
    for (const auto& skipped : estimate.skipped) ++reasons[skip_reason_name(skipped.reason)];
    std::string text = std::to_string(estimate.skipped.size()) + " of " +
                       std::to_string(estimate.clusters_found) + " clusters gave no polygon (";
    bool first = true;
    for (const auto& [reason, count] : reasons) {
      text += (first ? "" : ", ") + std::to_string(count) + " " + reason;
      first = false;
    }
    warnings.push_back(text + "); see \"skipped\" in the JSON report");
  }
  return warnings;
}

}  // namespace

void validate_estimation(const RegionGrowingOptions& e) {
  check_keys(estimation_keys(), e);
  if (e.max_cluster_size < e.min_cluster_size) {
    throw KeyError("max_cluster_size", "must be at least min_cluster_size (" +
                                           std::to_string(e.min_cluster_size) + ")");
  }
}

CloudEstimate load_and_estimate(const std::string& path, bool skip_bad_lines,
                                RegionGrowingOptions options, unsigned threads,
                                std::uint64_t max_memory_mb, const Progress& progress) {
  const auto start = Clock::now();
  progress("loading", 0.0);
  CloudEstimate input;
  input.loaded = load_cloud(path, skip_bad_lines, std::nullopt, max_memory_mb);
  input.load_seconds = seconds_since(start);
  progress.check_cancel();

  const PointCloud& cloud = input.loaded.cloud;
  options.threads = threads;
  if (cloud.size() < 3) {
    throw InputError(path, 0,
                     "has " + std::to_string(cloud.size()) + " points; a plane needs at least 3");
  }
  check_memory_budget(region_growing_memory(cloud.size(), options), max_memory_mb);
  try {
    input.estimate = estimate_mesh(cloud, options, progress);
  } catch (const NoPlaneFound& e) {
    // The cloud is readable; these options find no surface in it.
    throw UsageError(path + ": " + e.what());
  }
  input.warnings = estimation_warnings(input.estimate, options);
  add_read_warnings(input.loaded, input.warnings);
  return input;
}

ScalarField cluster_field(const MeshEstimate& estimate) {
  ScalarField field{"cluster", {}, true};
  field.values.reserve(estimate.point_cluster.size());
  for (const std::int32_t cluster : estimate.point_cluster) {
    field.values.push_back(static_cast<float>(cluster));
  }
  return field;
}

void add_estimation_json(const MeshEstimate& e, Json::Value& json) {
  json["clusters_found"] = Json::UInt64(e.clusters_found);
  json["clusters_used"] = Json::UInt64(e.clusters_used);
  json["clusters_skipped"] = Json::UInt64(e.skipped.size());
  json["covered_points"] = Json::UInt64(e.covered_points);
  json["covered_fraction"] = e.covered_fraction;
  json["edge_points"] = Json::UInt64(e.edge_points);

  Json::Value skipped(Json::arrayValue);
  for (const auto& s : e.skipped) {
    Json::Value entry(Json::objectValue);
    entry["cluster"] = Json::UInt64(s.cluster);
    entry["points"] = Json::UInt64(s.points);
    entry["reason"] = skip_reason_name(s.reason);
    entry["detail"] = s.detail;
    skipped.append(entry);
  }
  json["skipped"] = skipped;

  Json::Value regions(Json::objectValue);
  regions["grown"] = Json::UInt64(e.regions.regions);
  regions["too_small"] = Json::UInt64(e.regions.too_small);
  regions["too_small_points"] = Json::UInt64(e.regions.too_small_points);
  regions["too_large"] = Json::UInt64(e.regions.too_large);
  regions["too_large_points"] = Json::UInt64(e.regions.too_large_points);
  regions["largest"] = Json::UInt64(e.regions.largest);
  json["regions"] = regions;
}

void estimate_to_original(MeshEstimate& estimate, const Eigen::Vector3d& shift) {
  for (auto& vertex : estimate.mesh.vertices) vertex += shift;
  for (auto& plane : estimate.planes) {
    plane.centroid += shift;
    // normal . (p - shift) + offset = 0
    plane.offset -= plane.normal.dot(shift);
  }
}

Json::Value plane_json(const EstimatedPlane& p) {
  Json::Value plane(Json::objectValue);
  plane["cluster"] = Json::UInt64(p.cluster);
  plane["points"] = Json::UInt64(p.points);
  plane["inliers"] = Json::UInt64(p.inliers);
  plane["edge_points"] = Json::UInt64(p.edge_points);
  plane["normal"] = to_json(p.normal);
  plane["offset"] = p.offset;
  plane["centroid"] = to_json(p.centroid);
  plane["area"] = p.area;
  plane["triangles"] = Json::UInt64(p.hull_vertices);
  return plane;
}

void add_estimation_timings(const MeshEstimate& e, Json::Value& timings) {
  timings["normals_seconds"] = e.timings.normals_seconds;
  timings["region_growing_seconds"] = e.timings.region_growing_seconds;
  timings["planes_seconds"] = e.timings.planes_seconds;
  timings["hulls_seconds"] = e.timings.hulls_seconds;
}

}  // namespace occlusion::job
