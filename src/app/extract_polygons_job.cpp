#include "occlusion/app/extract_polygons_job.hpp"

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/obj_writer.hpp"
#include "region_growing_support.hpp"

namespace occlusion {

void validate(const ExtractPolygonsRequest& request) {
  if (request.path.empty()) {
    throw UsageError("no cloud given (occlusion.extract_polygons.path)");
  }
  check_keys(extract_polygons_keys(), request);
  job::validate_estimation(request.estimation);
}

ExtractPolygonsReport run_extract_polygons(const ExtractPolygonsRequest& request,
                                           const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  ExtractPolygonsReport report;
  report.request = request;

  job::CloudEstimate input =
      job::load_and_estimate(request.path, request.skip_bad_lines, request.estimation,
                             request.threads, request.max_memory_mb, progress);
  job::take_estimate(input, report);
  job::estimate_to_original(report.estimate, input.loaded.cloud.shift);
  report.shift = input.loaded.cloud.shift;

  if (!request.out.empty()) {
    ensure_directory(request.out);
    const std::string json_path = job::output_path(request.out, request.path, ".polygons.json");
    const std::string obj_path = job::output_path(request.out, request.path, ".polygons.obj");
    const std::string segmented_path =
        job::output_path(request.out, request.path, ".segmented.ply");
    OutputSet outputs;
    write_obj(outputs.add(obj_path), report.estimate.mesh,
              "planes found by region growing in " + request.path);
    write_cloud(outputs.add(segmented_path), input.loaded.cloud,
                {job::cluster_field(report.estimate)});
    job::commit_outputs(outputs, report, json_path, {json_path, obj_path, segmented_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

Json::Value to_json(const ExtractPolygonsReport& report) {
  const MeshEstimate& e = report.estimate;
  Json::Value json(Json::objectValue);
  json["job"] = "extract_polygons";
  json["input"] = report.request.path;
  json["global_shift"] = job::global_shift_json(report.shift);
  json["points"] = Json::UInt64(report.points);
  json["dropped_nan_points"] = Json::UInt64(report.dropped_nan);
  json["skipped_lines"] = Json::UInt64(report.skipped_lines);
  job::add_estimation_json(e, json);
  Json::Value planes(Json::arrayValue);
  for (const auto& plane : e.planes) planes.append(job::plane_json(plane));
  json["planes"] = planes;

  Json::Value mesh(Json::objectValue);
  mesh["vertices"] = Json::UInt64(e.mesh.vertices.size());
  mesh["faces"] = Json::UInt64(e.mesh.face_count());
  json["mesh"] = mesh;

  json["parameters"] = parameters_json(extract_polygons_keys(), report.request);

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  job::add_estimation_timings(e, timings);
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
