#include "occlusion/app/reconstruct_job.hpp"

#include <filesystem>
#include <set>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {

void validate(const ReconstructRequest& request) {
  if (request.path.empty()) {
    throw UsageError("no folder given (-recon ROOM_OR_AREA_FOLDER)");
  }
  check_keys(reconstruct_keys(), request);
  job::cloud_extension(request.format);
  if (request.out.empty()) throw KeyError("out", "must not be empty");
}

ReconstructReport run_reconstruct(const ReconstructRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  ReconstructReport report;
  report.request = request;

  progress("reading", 0.0);
  const job::LoadedCloud loaded = job::load_cloud(request.path, request.skip_bad_lines);
  const PointCloud& cloud = loaded.cloud;
  if (!cloud.has_labels()) {
    throw UsageError(request.path + " is not an S3DIS room or Area folder (no Annotations found)");
  }
  report.points = cloud.size();
  report.shift = cloud.shift;
  report.rooms = loaded.rooms;
  report.dropped_nan = loaded.dropped_nan;
  report.skipped_lines = loaded.skipped_lines;
  progress.check_cancel();

  report.classes.resize(cloud.class_names.size());
  std::vector<std::set<std::int32_t>> instances(cloud.class_names.size());
  for (std::size_t c = 0; c < cloud.class_names.size(); ++c) {
    report.classes[c].name = cloud.class_names[c];
  }
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto label = static_cast<std::size_t>(cloud.labels[i]);
    ++report.classes[label].points;
    if (cloud.has_instances()) instances[label].insert(cloud.instances[i]);
  }
  for (std::size_t c = 0; c < instances.size(); ++c) {
    report.classes[c].instances = instances[c].size();
  }

  progress("writing", 0.5);
  ensure_directory(request.out);
  const std::string cloud_path =
      job::output_path(request.out, request.path, "." + job::cloud_extension(request.format));
  const std::string json_path = job::output_path(request.out, request.path, ".recon.json");
  OutputSet outputs;
  write_cloud(outputs.add(cloud_path), cloud);
  job::commit_outputs(outputs, report, json_path, {cloud_path, json_path}, start);
  progress("done", 1.0);
  return report;
}

Json::Value to_json(const ReconstructReport& report) {
  Json::Value json(Json::objectValue);
  json["job"] = "reconstruct";
  json["input"] = report.request.path;
  json["global_shift"] = job::global_shift_json(report.shift);
  json["points"] = Json::UInt64(report.points);
  Json::Value classes(Json::arrayValue);
  for (std::size_t c = 0; c < report.classes.size(); ++c) {
    Json::Value entry(Json::objectValue);
    entry["id"] = Json::UInt64(c);
    entry["name"] = report.classes[c].name;
    entry["points"] = Json::UInt64(report.classes[c].points);
    entry["instances"] = Json::UInt64(report.classes[c].instances);
    classes.append(entry);
  }
  json["classes"] = classes;
  json["rooms"] = to_json(report.rooms);
  json["dropped_nan_points"] = Json::UInt64(report.dropped_nan);
  json["skipped_lines"] = Json::UInt64(report.skipped_lines);
  json["format"] = report.request.format;
  json["parameters"] = parameters_json(reconstruct_keys(), report.request);
  job::add_outputs_and_warnings(report, json);
  json["timings"]["total_seconds"] = report.total_seconds;
  return json;
}

}  // namespace occlusion
