#include "occlusion/app/register_job.hpp"

#include <filesystem>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/pose_file.hpp"

namespace occlusion {

namespace {

Json::Value fit_json(const RegistrationFit& fit) {
  Json::Value json(Json::objectValue);
  json["overlap"] = fit.overlap;
  json["rms"] = fit.rms;
  json["matched_points"] = Json::UInt64(fit.matched);
  return json;
}

// SOURCE.refined.EXT: the initial pose file's extension, which some formats
// need (3DTK's .pose).
std::string refined_pose_path(const RegisterRequest& request) {
  const std::string extension = std::filesystem::path(request.initial_pose).extension().string();
  return job::output_path(request.out, request.path,
                          ".refined" + (extension.empty() ? std::string(".txt") : extension));
}

}  // namespace

void validate(const RegisterRequest& request) {
  if (request.path.empty()) {
    throw UsageError("no source scan given (register SOURCE or occlusion.register.path)");
  }
  if (request.target.empty()) throw KeyError("target", "is required: the scan to register onto");
  if (request.initial_pose.empty()) {
    throw KeyError("initial_pose",
                   "is required: a pose file taking the source into the target's frame");
  }
  check_keys(register_keys(), request);
}

RegistrationOptions registration_options(const RegisterRequest& request) {
  RegistrationOptions options;
  options.method = parse_registration_method(request.method);
  options.levels = request.levels;
  options.finest_voxel = request.finest_voxel.value_or(0.0);
  options.max_distance = request.max_distance.value_or(0.0);
  options.max_iterations = request.max_iterations;
  options.min_overlap = request.min_overlap;
  options.max_rotation_deg = request.max_rotation;
  options.threads = request.threads;
  return options;
}

RegisterReport run_register(const RegisterRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  RegisterReport report;
  report.request = request;
  const ScanPose initial =
      request.pose_format == "auto"
          ? read_pose_file(request.initial_pose)
          : read_pose_file(request.initial_pose, pose_format_from_name(request.pose_format));
  report.pose_format = std::string(pose_format_name(initial.format));

  progress("reading", 0.0);
  const job::LoadedCloud source = job::load_cloud(request.path, request.skip_bad_lines);
  job::add_read_warnings(source, report.warnings);
  progress("reading", 0.5);
  const job::LoadedCloud target = job::load_cloud(request.target, request.skip_bad_lines);
  job::add_read_warnings(target, report.warnings);
  report.source_points = source.cloud.size();
  report.target_points = target.cloud.size();
  report.load_seconds = job::seconds_since(start);

  try {
    report.result = register_pair(source.cloud, target.cloud, initial.scan_to_scene,
                                  registration_options(request), progress);
  } catch (const RegistrationRefused& refused) {
    throw InputError(request.path, 0, refused.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(request.path, 0, e.what());
  }

  if (!request.out.empty()) {
    ensure_directory(request.out);
    const std::string pose_path = refined_pose_path(request);
    const std::string json_path = job::output_path(request.out, request.path, ".register.json");
    OutputSet outputs;
    ScanPose refined = initial;
    refined.scan_to_scene = report.result.refined;
    // Its own atomic write; the report, written last, lists it.
    write_pose_file(pose_path, refined);
    job::commit_outputs(outputs, report, json_path, {json_path, pose_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

Json::Value pose_json(const Eigen::Isometry3d& pose) {
  Json::Value json(Json::objectValue);
  Json::Value rows(Json::arrayValue);
  for (int r = 0; r < 4; ++r) {
    Json::Value row(Json::arrayValue);
    for (int c = 0; c < 4; ++c) row.append(pose.matrix()(r, c));
    rows.append(row);
  }
  json["matrix"] = rows;
  json["translation"] = to_json(Eigen::Vector3d(pose.translation()));
  const Eigen::AngleAxisd rotation(pose.linear());
  json["rotation_deg"] = rotation.angle() * 180.0 / 3.14159265358979323846;
  json["rotation_axis"] = to_json(Eigen::Vector3d(rotation.axis()));
  return json;
}

Json::Value to_json(const RegisterReport& report) {
  const RegistrationResult& r = report.result;
  Json::Value json(Json::objectValue);
  json["job"] = "register";
  json["input"] = report.request.path;
  json["target"] = report.request.target;
  json["initial_pose_file"] = report.request.initial_pose;
  json["pose_format"] = report.pose_format;
  json["source_points"] = Json::UInt64(report.source_points);
  json["target_points"] = Json::UInt64(report.target_points);
  json["rms"] = r.after.rms;
  json["overlap"] = r.after.overlap;
  json["converged"] = r.converged;
  json["evaluation_distance"] = r.evaluation_distance;
  json["before"] = fit_json(r.before);
  json["after"] = fit_json(r.after);
  json["initial_pose"] = pose_json(r.initial);
  json["refined_pose"] = pose_json(r.refined);
  Json::Value moved(Json::objectValue);
  moved["translation"] = r.moved_translation;
  moved["rotation_deg"] = r.moved_rotation_deg;
  json["moved"] = moved;
  json["source_spacing"] = r.source_spacing;
  json["target_spacing"] = r.target_spacing;
  Json::Value levels(Json::arrayValue);
  for (const RegistrationLevel& level : r.levels) {
    Json::Value entry(Json::objectValue);
    entry["voxel"] = level.voxel;
    entry["search_distance"] = level.search_distance;
    entry["source_points"] = Json::UInt64(level.source_points);
    entry["target_points"] = Json::UInt64(level.target_points);
    entry["iterations"] = level.iterations;
    entry["converged"] = level.converged;
    levels.append(entry);
  }
  json["levels"] = levels;
  json["parameters"] = parameters_json(register_keys(), report.request);
  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  timings["register_seconds"] = r.seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
