#include "occlusion/app/region_growing_job.hpp"

#include <cmath>
#include <map>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/obj_writer.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"

namespace occlusion {

namespace {

void require_at_least(std::uint64_t value, std::uint64_t least, const std::string& option) {
  if (value < least) throw UsageError(option + " must be at least " + std::to_string(least));
}

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

ScalarField cluster_field(const MeshEstimate& estimate) {
  ScalarField field{"cluster", {}, true};
  field.values.reserve(estimate.point_cluster.size());
  for (const std::int32_t cluster : estimate.point_cluster) {
    field.values.push_back(static_cast<float>(cluster));
  }
  return field;
}

void write_outputs(const PointCloud& cloud, RegionGrowingReport& report,
                   const job::Clock::time_point start) {
  const RegionGrowingRequest& request = report.request;
  ensure_directory(request.out);
  const std::string json_path = job::output_path(request.out, request.path, ".rgoc.json");
  const std::string obj_path = job::output_path(request.out, request.path, ".rgoc.obj");
  const std::string ply_path = job::output_path(request.out, request.path, ".rgoc.ply");
  const std::string segmented_path = job::output_path(request.out, request.path, ".segmented.ply");
  const TriangleMesh& mesh = report.estimate.mesh;
  write_obj(obj_path, mesh, "mesh estimated by region growing from " + request.path);
  write_mesh_ply(ply_path, mesh, report.occlusion.face_visible_fraction, "visible_fraction");
  write_cloud(segmented_path, cloud, {cluster_field(report.estimate)});
  report.outputs = {json_path, obj_path, ply_path, segmented_path};
  report.total_seconds = job::seconds_since(start);
  job::write_json_report(json_path, to_json(report));
}

Json::Value skipped_json(const MeshEstimate& estimate) {
  Json::Value skipped(Json::arrayValue);
  for (const auto& s : estimate.skipped) {
    Json::Value entry(Json::objectValue);
    entry["cluster"] = Json::UInt64(s.cluster);
    entry["points"] = Json::UInt64(s.points);
    entry["reason"] = skip_reason_name(s.reason);
    entry["detail"] = s.detail;
    skipped.append(entry);
  }
  return skipped;
}

Json::Value planes_json(const MeshEstimate& estimate, const MeshOcclusionResult& occlusion) {
  Json::Value planes(Json::arrayValue);
  for (const auto& p : estimate.planes) {
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
    plane["occlusion_level"] = occlusion.groups.at(p.cluster).occlusion_level;
    planes.append(plane);
  }
  return planes;
}

}  // namespace

void validate(const RegionGrowingRequest& request) {
  if (request.path.empty()) {
    throw UsageError("no cloud given (-rgoc CLOUD or occlusion.region_growing.path)");
  }
  request.viewpoints.validate();
  const RegionGrowingOptions& e = request.estimation;
  require_at_least(e.normal_k, 3, "--normal-k");
  require_at_least(e.neighbours, 1, "--neighbours");
  require_at_least(e.min_cluster_size, 1, "--min-cluster-size");
  if (e.max_cluster_size < e.min_cluster_size) {
    throw UsageError("--max-cluster-size must be at least --min-cluster-size (" +
                     std::to_string(e.min_cluster_size) + ")");
  }
  if (!(e.smoothness_degrees > 0.0 && e.smoothness_degrees <= 180.0)) {
    throw UsageError("--smoothness-degrees must be a number in (0, 180]");
  }
  job::require_non_negative(e.curvature_threshold, "--curvature-threshold");
  job::require_positive(e.ransac_distance, "--ransac-distance");
  require_at_least(e.ransac_iterations, 1, "--ransac-iterations");
  job::require_positive(request.samples_per_unit_area, "--samples-per-unit-area");
  job::require_non_negative(request.octree_resolution, "--octree-resolution");
}

void apply_config(const Config& config, RegionGrowingRequest& request) {
  const ConfigSection section(config, "region_growing");
  RegionGrowingOptions& e = request.estimation;
  std::uint64_t min_size = e.min_cluster_size, max_size = e.max_cluster_size;
  section.read_path("path", request.path);
  section.read_viewpoints(request.viewpoints);
  section.read("normal_k", e.normal_k);
  section.read("min_cluster_size", min_size);
  section.read("max_cluster_size", max_size);
  section.read("neighbours", e.neighbours);
  section.read("smoothness_degrees", e.smoothness_degrees);
  section.read("curvature_threshold", e.curvature_threshold);
  section.read("ransac_distance", e.ransac_distance);
  section.read("ransac_iterations", e.ransac_iterations);
  section.read("recover_edges", e.recover_edges);
  section.read("samples_per_unit_area", request.samples_per_unit_area);
  section.read("octree_resolution", request.octree_resolution);
  section.read("enable_acceleration", request.enable_acceleration);
  section.read("seed", request.seed);
  section.read("threads", request.threads);
  section.read("skip_bad_lines", request.skip_bad_lines);
  section.read_path("out", request.out);
  e.min_cluster_size = static_cast<std::size_t>(min_size);
  e.max_cluster_size = static_cast<std::size_t>(max_size);
}

RegionGrowingReport run_region_growing_occlusion(const RegionGrowingRequest& request,
                                                 const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  RegionGrowingReport report;
  report.request = request;

  progress("loading", 0.0);
  const job::LoadedCloud loaded = job::load_cloud(request.path, request.skip_bad_lines);
  const PointCloud& cloud = loaded.cloud;
  report.points = cloud.size();
  report.dropped_nan = loaded.dropped_nan;
  report.skipped_lines = loaded.skipped_lines;
  report.load_seconds = job::seconds_since(start);
  progress.check_cancel();

  RegionGrowingOptions estimation = request.estimation;
  estimation.threads = request.threads;
  if (cloud.size() < 3) {
    throw InputError(request.path, 0,
                     "has " + std::to_string(cloud.size()) + " points; a plane needs at least 3");
  }
  try {
    report.estimate = estimate_mesh(cloud, estimation, progress);
  } catch (const NoPlaneFound& e) {
    // The cloud is readable; these options find no surface in it.
    throw UsageError(request.path + ": " + e.what());
  }
  report.warnings = estimation_warnings(report.estimate, estimation);

  // Viewpoints on the cloud's box, as -poc and -fscan place them.
  const ViewpointChoice::Resolved viewpoints = job::resolve_for_cloud(request.viewpoints, cloud);
  report.viewpoint_names = viewpoints.names;
  MeshOcclusionOptions options;
  options.samples_per_unit_area = request.samples_per_unit_area;
  options.octree.min_cell_size = static_cast<float>(request.octree_resolution);
  options.octree.enable_acceleration = request.enable_acceleration;
  options.seed = request.seed;
  options.threads = request.threads;
  report.occlusion =
      compute_mesh_occlusion(report.estimate.mesh, viewpoints.positions, options, progress);

  if (!request.out.empty()) write_outputs(cloud, report, start);
  report.total_seconds = job::seconds_since(start);
  return report;
}

Json::Value to_json(const RegionGrowingReport& report) {
  const RegionGrowingRequest& q = report.request;
  const MeshEstimate& e = report.estimate;
  const MeshOcclusionResult& r = report.occlusion;
  Json::Value json(Json::objectValue);
  json["job"] = "region_growing_occlusion";
  json["input"] = q.path;
  json["occlusion_level"] = r.occlusion_level;
  json["visible_area"] = r.visible_area;
  json["total_area"] = r.total_area;
  json["points"] = Json::UInt64(report.points);
  json["dropped_nan_points"] = Json::UInt64(report.dropped_nan);
  json["skipped_lines"] = Json::UInt64(report.skipped_lines);
  json["clusters_found"] = Json::UInt64(e.clusters_found);
  json["clusters_used"] = Json::UInt64(e.clusters_used);
  json["clusters_skipped"] = Json::UInt64(e.skipped.size());
  json["covered_points"] = Json::UInt64(e.covered_points);
  json["covered_fraction"] = e.covered_fraction;
  json["edge_points"] = Json::UInt64(e.edge_points);
  json["skipped"] = skipped_json(e);

  Json::Value regions(Json::objectValue);
  regions["grown"] = Json::UInt64(e.regions.regions);
  regions["too_small"] = Json::UInt64(e.regions.too_small);
  regions["too_small_points"] = Json::UInt64(e.regions.too_small_points);
  regions["too_large"] = Json::UInt64(e.regions.too_large);
  regions["too_large_points"] = Json::UInt64(e.regions.too_large_points);
  regions["largest"] = Json::UInt64(e.regions.largest);
  json["regions"] = regions;
  json["planes"] = planes_json(e, r);

  Json::Value mesh(Json::objectValue);
  mesh["vertices"] = Json::UInt64(e.mesh.vertices.size());
  mesh["faces"] = Json::UInt64(r.faces);
  mesh["samples"] = Json::UInt64(r.samples);
  mesh["rays"] = Json::UInt64(r.rays);
  json["mesh"] = mesh;

  Json::Value viewpoints(Json::arrayValue);
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    Json::Value vp = job::viewpoint_json(report.viewpoint_names.at(v), r.viewpoints[v].position);
    vp["visible_area"] = r.viewpoints[v].visible_area;
    vp["visible_fraction"] = r.viewpoints[v].visible_fraction;
    viewpoints.append(vp);
  }
  json["viewpoints"] = viewpoints;

  const RegionGrowingOptions& o = q.estimation;
  Json::Value parameters = q.viewpoints.to_json();
  parameters["normal_k"] = o.normal_k;
  parameters["min_cluster_size"] = Json::UInt64(o.min_cluster_size);
  parameters["max_cluster_size"] = Json::UInt64(o.max_cluster_size);
  parameters["neighbours"] = o.neighbours;
  parameters["smoothness_degrees"] = o.smoothness_degrees;
  parameters["curvature_threshold"] = o.curvature_threshold;
  parameters["ransac_distance"] = o.ransac_distance;
  parameters["ransac_iterations"] = o.ransac_iterations;
  parameters["recover_edges"] = o.recover_edges;
  parameters["samples_per_unit_area"] = q.samples_per_unit_area;
  parameters["octree_resolution"] = q.octree_resolution;
  parameters["enable_acceleration"] = q.enable_acceleration;
  parameters["seed"] = Json::UInt64(q.seed);
  parameters["threads"] = q.threads;
  json["parameters"] = parameters;

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  timings["normals_seconds"] = e.timings.normals_seconds;
  timings["region_growing_seconds"] = e.timings.region_growing_seconds;
  timings["planes_seconds"] = e.timings.planes_seconds;
  timings["hulls_seconds"] = e.timings.hulls_seconds;
  timings["sampling_seconds"] = r.timings.sampling_seconds;
  timings["build_seconds"] = r.timings.build_seconds;
  timings["trace_seconds"] = r.timings.trace_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;

  json["outputs"] = to_json(report.outputs);
  json["warnings"] = to_json(report.warnings);
  return json;
}

}  // namespace occlusion
