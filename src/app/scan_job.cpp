#include "occlusion/app/scan_job.hpp"

#include <cmath>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/first_station_field.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/no_return_pile.hpp"
#include "occlusion/app/work_budget.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {

namespace {

std::vector<ClassVisibility> per_class(const PointCloud& cloud, const ScanResult& result) {
  std::vector<ClassVisibility> classes;
  if (!cloud.has_labels()) return classes;
  std::int32_t max_label = -1;
  for (const auto label : cloud.labels) max_label = std::max(max_label, label);
  const std::size_t count =
      std::max(cloud.class_names.size(), static_cast<std::size_t>(max_label + 1));
  classes.resize(count);
  for (std::size_t c = 0; c < count; ++c) {
    classes[c].name = c < cloud.class_names.size() ? cloud.class_names[c] : std::to_string(c);
  }
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.labels[i] < 0) continue;
    ClassVisibility& c = classes[static_cast<std::size_t>(cloud.labels[i])];
    ++c.points;
    c.visible += result.visible_count[i] > 0 ? 1 : 0;
  }
  for (auto& c : classes) {
    c.visible_fraction =
        c.points > 0 ? static_cast<double>(c.visible) / static_cast<double>(c.points) : 0.0;
  }
  return classes;
}

}  // namespace

void validate(const ScanRequest& request) {
  if (request.path.empty()) {
    throw UsageError("no cloud given (-fscan CLOUD or occlusion.scan.path)");
  }
  check_keys(scan_keys(), request);
  request.viewpoints.validate();
  validate(station_filter(request));
  job::parse_frame(request.frame);
  job::parse_up(request.up);
  job::cloud_extension(request.format);
}

ScanReport run_scan_on(const PointCloud& cloud, const ViewpointChoice::Resolved& viewpoints,
                       const ScanRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  ScanReport report;
  report.request = request;
  report.viewpoint_names = viewpoints.names;
  report.viewpoint_source = viewpoints.source;
  report.frame = viewpoints.frame;
  report.warnings.insert(report.warnings.end(), viewpoints.warnings.begin(),
                         viewpoints.warnings.end());
  warn_no_return_piles(cloud, request.max_range, report.warnings);
  report.shift = cloud.shift;
  for (const auto& position : viewpoints.positions) {
    report.viewpoint_positions.push_back(cloud.to_original(position));
  }
  check_memory_budget(
      scan_memory(cloud.size(), viewpoints.positions.size(), request.primitive == "disc"),
      request.max_memory_mb);
  check_work_budget(
      scan_work(cloud.size(), viewpoints.positions.size(), request.enable_acceleration),
      request.max_work);
  const job::PointModel model = job::choose_point_model(cloud, job::point_settings(request),
                                                        "-fscan", report.warnings, progress);
  report.point_model = model.report;

  ScanOptions options;
  options.point_radius = report.point_model.radius.radius;
  options.surfels = model.surfels ? &*model.surfels : nullptr;
  options.self_tolerance = request.self_tolerance;
  options.octree.min_cell_size = static_cast<float>(request.octree_resolution);
  options.octree.enable_acceleration = request.enable_acceleration;
  options.threads = request.threads;
  report.field_of_view = job::station_field_of_view(cloud, request.path, report.warnings);
  options.field_of_view = report.field_of_view;
  if (report.field_of_view) report.field_of_view_station = cloud.stations.front();
  report.result = scan_cloud(cloud, viewpoints.positions, options, progress);
  report.classes = per_class(cloud, report.result);
  report.total_seconds = job::seconds_since(start);
  return report;
}

std::vector<bool> seen_points(const ScanResult& result) {
  std::vector<bool> seen(result.visible_count.size());
  for (std::size_t i = 0; i < seen.size(); ++i) seen[i] = result.visible_count[i] > 0;
  return seen;
}

ScanReport run_scan(const ScanRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  progress("loading", 0.0);
  job::LoadedCloud loaded =
      job::load_cloud(request.path, request.skip_bad_lines, std::nullopt, request.max_memory_mb);
  const StationFilterReport filtered =
      apply_station_filter(loaded.cloud, station_filter(request), request.path);
  job::name_classes(loaded.cloud, request.path, request.class_names_path);
  const PointCloud& cloud = loaded.cloud;
  const double load_seconds = job::seconds_since(start);
  progress.check_cancel();

  ScanReport report = run_scan_on(
      cloud, job::resolve_for_cloud(request.viewpoints, cloud, request.frame, request.up), request,
      progress);
  report.dropped_nan = loaded.dropped_nan;
  report.skipped_lines = loaded.skipped_lines;
  job::add_read_warnings(loaded, report.warnings);
  report.station_filter = filtered;
  report.load_seconds = load_seconds;

  if (!request.out.empty()) {
    ensure_directory(request.out);
    const std::string extension = "." + job::cloud_extension(request.format);
    const std::string scanned_path =
        job::output_path(request.out, request.path, ".scan" + extension);
    const std::string full_path =
        job::output_path(request.out, request.path, ".scan_full" + extension);
    const std::string json_path = job::output_path(request.out, request.path, ".fscan.json");

    ScalarField visible_count{"visible_count", {}, true};
    visible_count.values.reserve(cloud.size());
    for (const auto count : report.result.visible_count) {
      visible_count.values.push_back(static_cast<float>(count));
    }
    OutputSet outputs;
    write_cloud(outputs.add(scanned_path), cloud.subset(seen_points(report.result)));
    write_cloud(outputs.add(full_path), cloud,
                {visible_count, first_station_field(report.result.first_viewpoint)});
    job::commit_outputs(outputs, report, json_path, {json_path, scanned_path, full_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

Json::Value to_json(const ScanReport& report) {
  const ScanRequest& q = report.request;
  const ScanResult& r = report.result;
  Json::Value json(Json::objectValue);
  json["job"] = "scan";
  json["input"] = q.path;
  json["global_shift"] = job::global_shift_json(report.shift);
  json["visible_fraction"] = r.visible_fraction;
  json["points"] = Json::UInt64(r.visible_count.size());
  json["visible_points"] = Json::UInt64(r.visible_points);
  json["dropped_nan_points"] = Json::UInt64(report.dropped_nan);
  json["skipped_lines"] = Json::UInt64(report.skipped_lines);
  json["station_filter"] = station_filter_json(report.station_filter);

  Json::Value viewpoints(Json::arrayValue);
  const double points = static_cast<double>(std::max<std::size_t>(r.visible_count.size(), 1));
  for (std::size_t v = 0; v < report.viewpoint_positions.size(); ++v) {
    Json::Value entry =
        job::viewpoint_json(report.viewpoint_names.at(v), report.viewpoint_positions[v]);
    entry["visible_points"] = Json::UInt64(r.seen_by_viewpoint.at(v));
    entry["visible_fraction"] = static_cast<double>(r.seen_by_viewpoint[v]) / points;
    entry["only_points"] = Json::UInt64(r.only_by_viewpoint.at(v));
    entry["only_fraction"] = static_cast<double>(r.only_by_viewpoint[v]) / points;
    viewpoints.append(entry);
  }
  // With the viewpoints' only_fraction these add up to 1.
  const std::size_t unseen = r.visible_count.size() - r.visible_points;
  json["seen_by_several_points"] = Json::UInt64(r.seen_by_several);
  json["seen_by_several_fraction"] = static_cast<double>(r.seen_by_several) / points;
  json["seen_by_none_points"] = Json::UInt64(unseen);
  json["seen_by_none_fraction"] = static_cast<double>(unseen) / points;
  json["viewpoints"] = viewpoints;
  json["viewpoint_source"] = report.viewpoint_source;
  json["station_field_of_view"] = job::station_field_of_view_json(
      report.field_of_view, report.field_of_view_station, r.outside_view_rays);

  Json::Value classes(Json::arrayValue);
  for (const auto& c : report.classes) {
    Json::Value entry(Json::objectValue);
    entry["name"] = c.name;
    entry["points"] = Json::UInt64(c.points);
    entry["visible_points"] = Json::UInt64(c.visible);
    entry["visible_fraction"] = c.visible_fraction;
    classes.append(entry);
  }
  json["classes"] = classes;

  Json::Value parameters = parameters_json(scan_keys(), q);
  // The radius and tolerance in force, not "auto" or the "-1 = 2 x radius"
  // shorthand (discs: the median radius; their reach is per point and ray).
  const double radius = report.point_model.radius.radius;
  parameters["point_radius"] = radius;
  parameters["point_radius_auto"] = report.point_model.radius.automatic;
  if (q.self_tolerance >= 0.0) {
    parameters["self_tolerance"] = q.self_tolerance;
  } else if (q.primitive == "sphere") {
    parameters["self_tolerance"] = 2.0 * radius;
  }
  job::stations_in_parameters(report.viewpoint_source, parameters);
  json["parameters"] = parameters;
  if (!report.frame.isNull()) json["frame"] = report.frame;
  json["point_model"] = job::point_model_json(report.point_model);
  json["point_spacing"] = job::point_radius_json(report.point_model.radius);

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  if (report.point_model.surfels) timings["surfel_seconds"] = report.point_model.surfels->seconds;
  timings["build_seconds"] = r.build_seconds;
  timings["trace_seconds"] = r.trace_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
