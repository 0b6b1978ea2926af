#include "occlusion/app/region_growing_job.hpp"

#include <cmath>

#include "job_support.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/work_budget.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/obj_writer.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"
#include "region_growing_support.hpp"

namespace occlusion {

namespace {

void write_outputs(const PointCloud& cloud, RegionGrowingReport& report,
                   const job::Clock::time_point start) {
  const RegionGrowingRequest& request = report.request;
  ensure_directory(request.out);
  const std::string json_path = job::output_path(request.out, request.path, ".rgoc.json");
  const std::string obj_path = job::output_path(request.out, request.path, ".rgoc.obj");
  const std::string ply_path = job::output_path(request.out, request.path, ".rgoc.ply");
  const std::string segmented_path = job::output_path(request.out, request.path, ".segmented.ply");
  const TriangleMesh& mesh = report.estimate.mesh;
  OutputSet outputs;
  write_obj(outputs.add(obj_path), mesh, "mesh estimated by region growing from " + request.path);
  write_mesh_ply(outputs.add(ply_path), mesh, report.occlusion.face_visible_fraction,
                 "visible_fraction");
  write_cloud(outputs.add(segmented_path), cloud, {job::cluster_field(report.estimate)});
  job::commit_outputs(outputs, report, json_path, {json_path, obj_path, ply_path, segmented_path},
                      start);
}

Json::Value planes_json(const MeshEstimate& estimate, const MeshOcclusionResult& occlusion) {
  Json::Value planes(Json::arrayValue);
  for (const auto& p : estimate.planes) {
    Json::Value plane = job::plane_json(p);
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
  check_keys(region_growing_keys(), request);
  request.viewpoints.validate();
  job::validate_estimation(request.estimation);
}

RegionGrowingReport run_region_growing_occlusion(const RegionGrowingRequest& request,
                                                 const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  RegionGrowingReport report;
  report.request = request;

  job::CloudEstimate input =
      job::load_and_estimate(request.path, request.skip_bad_lines, request.estimation,
                             request.threads, request.max_memory_mb, progress);
  job::take_estimate(input, report);
  const PointCloud& cloud = input.loaded.cloud;

  // Viewpoints on the cloud's box, as -poc and -fscan place them.
  const ViewpointChoice::Resolved viewpoints = job::resolve_for_cloud(request.viewpoints, cloud);
  report.viewpoint_names = viewpoints.names;
  report.samples_per_unit_area = density_for_min_samples(
      report.estimate.mesh, request.samples_per_unit_area, request.min_samples);
  // The budget holds the samples min_samples asks for, not only the density's.
  MemoryEstimate memory = mesh_occlusion_memory(report.estimate.mesh, report.samples_per_unit_area,
                                                viewpoints.positions.size());
  if (report.samples_per_unit_area > request.samples_per_unit_area) memory.lower = "min_samples";
  check_memory_budget(memory, request.max_memory_mb);
  check_work_budget(mesh_occlusion_work(report.estimate.mesh, report.samples_per_unit_area,
                                        viewpoints.positions.size(), request.enable_acceleration),
                    request.max_work);
  const MeshOcclusionOptions options =
      mesh_occlusion_options(request, report.samples_per_unit_area);
  // Traced in the cloud's local frame, reported and written in the file's.
  report.occlusion =
      compute_mesh_occlusion(report.estimate.mesh, viewpoints.positions, options, progress);
  job::viewpoints_to_original(report.occlusion.viewpoints, cloud);
  job::estimate_to_original(report.estimate, cloud.shift);
  report.shift = cloud.shift;

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
  json["global_shift"] = job::global_shift_json(report.shift);
  json["occlusion_level"] = r.occlusion_level;
  json["visible_area"] = r.visible_area;
  json["total_area"] = r.total_area;
  json["points"] = Json::UInt64(report.points);
  json["dropped_nan_points"] = Json::UInt64(report.dropped_nan);
  json["skipped_lines"] = Json::UInt64(report.skipped_lines);
  job::add_estimation_json(e, json);
  json["planes"] = planes_json(e, r);

  Json::Value mesh(Json::objectValue);
  mesh["vertices"] = Json::UInt64(e.mesh.vertices.size());
  mesh["faces"] = Json::UInt64(r.faces);
  mesh["samples"] = Json::UInt64(r.samples);
  // The sample budget: the density asked for, the minimum count, and the
  // density used (raised when the asked one gave fewer samples).
  Json::Value sampling(Json::objectValue);
  sampling["requested_samples_per_unit_area"] = q.samples_per_unit_area;
  sampling["min_samples"] = Json::UInt64(q.min_samples);
  sampling["samples_per_unit_area"] = report.samples_per_unit_area;
  sampling["samples"] = Json::UInt64(r.samples);
  sampling["raised"] = report.samples_per_unit_area > q.samples_per_unit_area;
  mesh["sampling"] = sampling;
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

  json["parameters"] = parameters_json(region_growing_keys(), q);

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  job::add_estimation_timings(e, timings);
  timings["sampling_seconds"] = r.timings.sampling_seconds;
  timings["build_seconds"] = r.timings.build_seconds;
  timings["trace_seconds"] = r.timings.trace_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;

  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
