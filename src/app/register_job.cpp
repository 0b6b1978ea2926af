#include "occlusion/app/register_job.hpp"

#include <filesystem>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/pose_file.hpp"
#include "occlusion/io/scene_project.hpp"

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
  if (is_project_file(request.path)) {
    if (!request.target.empty() || !request.initial_pose.empty()) {
      throw KeyError(request.target.empty() ? "initial_pose" : "target",
                     "is for a pair: a project's scans are registered onto its first scan from "
                     "the poses the project gives");
    }
    check_keys(register_keys(), request);
    return;
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

namespace {

// One scan of a project as read on its own: in the scene's frame (its pose
// applied) or, with `own_frame`, in its scanner's frame.
PointCloud read_project_scan(SceneScan scan, bool own_frame, const RegisterRequest& request,
                             std::vector<std::string>& warnings) {
  if (own_frame) scan.pose->scan_to_scene = Eigen::Isometry3d::Identity();
  CloudReadOptions options;
  options.skip_bad_lines = request.skip_bad_lines;
  CloudReadReport read;
  PointCloud cloud = read_scene({scan}, request.path, options, read);
  for (const auto& warning : read.warnings) warnings.push_back(warning);
  return cloud;
}

// Each scan after the first registered onto the first, from its pose; the
// project written back with the refined poses (inline, in their formats), as
// OUT/NAME.refined.project.json.
RegisterReport run_register_project(const RegisterRequest& request, const Progress& progress) {
  const auto start = job::Clock::now();
  RegisterReport report;
  report.request = request;
  std::vector<SceneScan> scans = read_project_file(request.path);
  if (scans.size() < 2) {
    throw InputError(request.path, 0, "a project to register needs two scans or more");
  }
  for (const SceneScan& scan : scans) {
    if (!scan.pose) {
      throw InputError(request.path, scan.line,
                       scan.path +
                           " has no pose in the project (it is placed as its own file "
                           "says); give it a pose to refine");
    }
  }
  const PointCloud target = read_project_scan(scans.front(), false, request, report.warnings);
  report.target_points = target.size();
  report.pose_format = std::string(pose_format_name(scans.front().pose->format));
  for (std::size_t i = 1; i < scans.size(); ++i) {
    SceneScan& scan = scans[i];
    const PointCloud source = read_project_scan(scan, true, request, report.warnings);
    ProjectScanRegistration entry;
    entry.path = scan.path;
    entry.points = source.size();
    const Progress step{
        [&](const std::string& stage, double fraction) {
          progress("scan " + std::to_string(i + 1) + " of " + std::to_string(scans.size()) + ": " +
                       stage,
                   (static_cast<double>(i - 1) + fraction) / static_cast<double>(scans.size() - 1));
        },
        progress.cancel};
    try {
      entry.result = register_pair(source, target, scan.pose->scan_to_scene,
                                   registration_options(request), step);
    } catch (const RegistrationRefused& refused) {
      throw InputError(request.path, scan.line, scan.path + ": " + refused.what());
    } catch (const std::invalid_argument& e) {
      throw InputError(request.path, scan.line, scan.path + ": " + e.what());
    }
    scan.pose->scan_to_scene = entry.result.refined;
    // Inline from now on: the user's pose files are left as they were.
    scan.pose_path.clear();
    scan.named_pose_file.clear();
    report.result = entry.result;
    report.source_points = entry.points;
    report.project_scans.push_back(std::move(entry));
  }
  if (!request.out.empty()) {
    ensure_directory(request.out);
    const std::filesystem::path project_dir =
        std::filesystem::absolute(request.path).parent_path().lexically_normal();
    const bool same_dir = std::filesystem::equivalent(project_dir, request.out);
    // Named paths (a scan's and its pose file's) are relative to the
    // project's folder: elsewhere, resolved ones, made absolute (a resolved
    // path may still be relative to the working folder, which the written
    // project's folder is not).
    const auto absolute = [](const std::string& path) {
      return std::filesystem::absolute(path).lexically_normal().string();
    };
    for (SceneScan& scan : scans) {
      if (same_dir) continue;
      scan.named_path.clear();
      scan.path = absolute(scan.path);
      scan.named_pose_file.clear();
      if (!scan.pose_path.empty()) scan.pose_path = absolute(scan.pose_path);
    }
    std::string name = std::filesystem::path(request.path).filename().string();
    name = name.substr(0, name.size() - std::string(kProjectFileSuffix).size());
    const std::string project_path =
        (std::filesystem::path(request.out) / (name + ".refined" + kProjectFileSuffix)).string();
    const std::string json_path =
        (std::filesystem::path(request.out) / (name + ".register.json")).string();
    write_project_file(project_path, scans);
    OutputSet outputs;
    job::commit_outputs(outputs, report, json_path, {json_path, project_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

}  // namespace

RegisterReport run_register(const RegisterRequest& request, const Progress& progress) {
  validate(request);
  if (is_project_file(request.path)) return run_register_project(request, progress);
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
  json["rotation_deg"] = rotation_degrees(pose);
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
  if (!report.project_scans.empty()) {
    Json::Value scans(Json::arrayValue);
    for (const ProjectScanRegistration& scan : report.project_scans) {
      Json::Value entry(Json::objectValue);
      entry["path"] = scan.path;
      entry["points"] = Json::UInt64(scan.points);
      entry["rms"] = scan.result.after.rms;
      entry["overlap"] = scan.result.after.overlap;
      entry["before"] = fit_json(scan.result.before);
      entry["converged"] = scan.result.converged;
      entry["refined_pose"] = pose_json(scan.result.refined);
      Json::Value scan_moved(Json::objectValue);
      scan_moved["translation"] = scan.result.moved_translation;
      scan_moved["rotation_deg"] = scan.result.moved_rotation_deg;
      entry["moved"] = scan_moved;
      Json::Value iterations(Json::arrayValue);
      for (const RegistrationLevel& level : scan.result.levels) iterations.append(level.iterations);
      entry["iterations"] = iterations;
      scans.append(entry);
    }
    json["project_scans"] = scans;
  }
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
