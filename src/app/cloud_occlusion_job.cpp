#include "occlusion/app/cloud_occlusion_job.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/no_return_pile.hpp"
#include "occlusion/app/work_budget.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/polygon_file.hpp"

namespace occlusion {

namespace {

DirectionSampling parse_sampling(const std::string& name) {
  if (name == "uniform") return DirectionSampling::kUniform;
  if (name == "fibonacci") return DirectionSampling::kFibonacci;
  throw KeyError("sampling", "must be uniform or fibonacci, got '" + name + "'");
}

// Which points are exterior structure: those whose class is in `classes`.
std::vector<bool> exterior_mask(const PointCloud& cloud, const std::vector<std::string>& classes,
                                const std::string& path) {
  if (!cloud.has_labels() || cloud.class_names.empty()) {
    throw KeyError("exterior", "needs a labelled cloud with class names; " + path +
                                   " has none (use an S3DIS folder, or a PLY written by -recon)");
  }
  std::vector<bool> is_exterior_class(cloud.class_names.size(), false);
  for (const auto& name : classes) {
    const auto it = std::find(cloud.class_names.begin(), cloud.class_names.end(), name);
    if (it == cloud.class_names.end()) {
      std::string known;
      for (const auto& n : cloud.class_names) known += (known.empty() ? "" : ", ") + n;
      throw KeyError("exterior_classes", "names no class of " + path + ": '" + name + "'" +
                                             " (classes: " + known + ")");
    }
    is_exterior_class[static_cast<std::size_t>(it - cloud.class_names.begin())] = true;
  }
  std::vector<bool> mask(cloud.size(), false);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::int32_t label = cloud.labels[i];
    mask[i] = label >= 0 && is_exterior_class[static_cast<std::size_t>(label)];
  }
  return mask;
}

void write_escapes(const std::string& path, const CloudOcclusionResult& result) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "viewpoint,dx,dy,dz\n" << std::setprecision(7);
    for (std::size_t v = 0; v < result.viewpoints.size(); ++v) {
      for (const auto& d : result.viewpoints[v].escape_directions) {
        out << v << ',' << d.x() << ',' << d.y() << ',' << d.z() << '\n';
      }
    }
  });
}

Json::Value numbers_json(const std::vector<double>& numbers) {
  Json::Value json(Json::arrayValue);
  for (const double x : numbers) json.append(x);
  return json;
}

// The frame's field of view, when the cloud is a single-view frame, with why it is one.
std::optional<FieldOfView> single_view_field(const PointCloud& cloud,
                                             const CloudOcclusionRequest& request,
                                             CloudOcclusionReport& report) {
  const SensorFrame& sensor = cloud.sensor;
  if (!request.field_of_view.empty()) {
    report.field_of_view_source = "field_of_view setting";
    return field_of_view_from_angles(sensor, request.field_of_view[0], request.field_of_view[1]);
  }
  if (!sensor.single_view()) return std::nullopt;
  report.field_of_view_source = sensor.organised()
                                    ? "organised frame " + std::to_string(sensor.width) + " x " +
                                          std::to_string(sensor.height)
                                    : std::string("VIEWPOINT header");
  try {
    return measure_field_of_view(cloud);
  } catch (const std::invalid_argument& e) {
    report.warnings.push_back(request.path + " looks like a single-view frame (" +
                              report.field_of_view_source + ") but " + e.what() +
                              "; all rays are counted (set field_of_view to override)");
    report.field_of_view_source.clear();
    return std::nullopt;
  }
}

Json::Value field_of_view_json(const FieldOfView& view, const std::string& source) {
  Json::Value json(Json::objectValue);
  json["source"] = source;
  json["horizontal_degrees"] = view.horizontal_degrees();
  json["vertical_degrees"] = view.vertical_degrees();
  json["tan_x"] = numbers_json({view.x_lo, view.x_hi});
  json["tan_y"] = numbers_json({view.y_lo, view.y_hi});
  return json;
}

std::string degrees(double angle) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << angle << " deg";
  return text.str();
}

// What the rays outside the view are outside of: no sensor ever measured
// those directions, so they tell nothing of gaps in the scene.
std::string outside_view_reason(const CloudOcclusionReport& report) {
  if (report.field_of_view) {
    return "outside the frame's " + degrees(report.field_of_view->horizontal_degrees()) + " x " +
           degrees(report.field_of_view->vertical_degrees()) + " field of view (" +
           report.field_of_view_source + "): directions its sensor never measured";
  }
  if (report.station_field_of_view) {
    const SphericalFieldOfView& view = *report.station_field_of_view;
    return "outside the field of view of station '" + report.field_of_view_station.name +
           "' (elevation " + degrees(view.elevation_lo_degrees()) + " to " +
           degrees(view.elevation_hi_degrees()) + ", " +
           (view.full_turn ? std::string("a full turn")
                           : "azimuth window " + degrees(view.azimuth_span_degrees())) +
           "): directions it never measured";
  }
  return "";
}

Json::Value result_json(const CloudOcclusionResult& r, const std::vector<std::string>& names,
                        const std::string& outside_why) {
  Json::Value json(Json::objectValue);
  json["occlusion_level"] = r.occlusion_level;
  json["level_counts"] = level_counts_text(ray_counts(r), outside_why);
  json["rays_in_view"] = Json::UInt64(ray_counts(r).rays_in_view());
  json["rays"] = Json::UInt64(r.rays);
  json["hits"] = Json::UInt64(r.hits);
  json["through_openings"] = Json::UInt64(r.through_openings);
  json["occlusion_rays"] = Json::UInt64(r.occlusion_rays);
  json["outside_view_rays"] = Json::UInt64(r.outside_view_rays);
  json["blocking_points"] = Json::UInt64(r.blocking_points);
  Json::Value viewpoints(Json::arrayValue);
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    const ViewpointRays& vp = r.viewpoints[v];
    Json::Value entry = job::viewpoint_json(names.at(v), vp.position);
    entry["occlusion_level"] = vp.occlusion_level;
    entry["level_counts"] = level_counts_text(ray_counts(vp), outside_why);
    entry["rays_in_view"] = Json::UInt64(ray_counts(vp).rays_in_view());
    entry["rays"] = Json::UInt64(vp.rays);
    entry["hits"] = Json::UInt64(vp.hits);
    entry["through_openings"] = Json::UInt64(vp.through_openings);
    entry["occlusion_rays"] = Json::UInt64(vp.occlusion_rays);
    entry["outside_view_rays"] = Json::UInt64(vp.outside_view_rays);
    viewpoints.append(entry);
  }
  json["viewpoints"] = viewpoints;
  return json;
}

}  // namespace

void validate(const CloudOcclusionRequest& request) {
  if (request.path.empty()) {
    throw UsageError("no cloud given (-poc CLOUD or occlusion.point_cloud.path)");
  }
  check_keys(cloud_occlusion_keys(), request);
  request.viewpoints.validate();
  validate(station_filter(request));
  job::parse_frame(request.frame);
  job::parse_up(request.up);
  parse_sampling(request.sampling);
  if (!request.field_of_view.empty() && request.field_of_view.size() != 2) {
    throw KeyError("field_of_view", "takes two angles (horizontal, vertical) in degrees");
  }
  if (request.exterior && request.exterior_classes.empty()) {
    throw KeyError("exterior_classes", "must name at least one class");
  }
}

std::vector<PlanarPolygon> read_openings(const std::string& polygon_path) {
  std::vector<PlanarPolygon> openings;
  if (polygon_path.empty()) return openings;
  for (const auto& boundary : read_polygons(polygon_path)) {
    try {
      openings.emplace_back(boundary);
    } catch (const std::invalid_argument& e) {
      throw InputError(polygon_path, 0,
                       "opening " + std::to_string(openings.size() + 1) + ": " + e.what());
    }
  }
  return openings;
}

CloudOcclusionReport run_cloud_occlusion_on(const PointCloud& cloud,
                                            const ViewpointChoice::Resolved& viewpoints,
                                            const std::vector<PlanarPolygon>& openings,
                                            const CloudOcclusionRequest& request,
                                            const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  CloudOcclusionReport report;
  report.request = request;
  report.viewpoint_names = viewpoints.names;
  report.viewpoint_source = viewpoints.source;
  report.frame = viewpoints.frame;
  report.shift = cloud.shift;
  report.warnings.insert(report.warnings.end(), viewpoints.warnings.begin(),
                         viewpoints.warnings.end());
  warn_no_return_piles(cloud, request.max_range, report.warnings);
  report.openings = openings.size();
  const std::vector<PlanarPolygon> local_openings =
      job::openings_in_frame(openings, cloud, request.polygon_path);
  check_memory_budget(
      cloud_occlusion_memory(cloud.size(), viewpoints.positions.size(), request.num_rays_per_vp,
                             request.escape_directions || !request.out.empty(),
                             request.primitive == "disc"),
      request.max_memory_mb);
  check_work_budget(
      cloud_occlusion_work(cloud.size(), viewpoints.positions.size(), request.num_rays_per_vp,
                           request.exterior, request.enable_acceleration),
      request.max_work);
  job::PointModel model = job::choose_point_model(cloud, job::point_settings(request), "-poc",
                                                  report.warnings, progress);
  report.point_model = model.report;

  CloudOcclusionOptions options;
  options.point_radius = report.point_model.radius.radius;
  options.num_rays_per_vp = static_cast<std::size_t>(request.num_rays_per_vp);
  options.sampling = parse_sampling(request.sampling);
  options.light_radius = request.light_radius;
  options.octree.min_cell_size = static_cast<float>(request.octree_resolution);
  options.octree.enable_acceleration = request.enable_acceleration;
  options.seed = request.seed;
  options.threads = request.threads;
  options.keep_escape_directions = request.escape_directions || !request.out.empty();
  report.field_of_view = single_view_field(cloud, request, report);
  options.field_of_view = report.field_of_view;
  // A field_of_view setting says how to take the cloud; else a laser station's own window.
  if (!report.field_of_view) {
    report.station_field_of_view = job::station_field_of_view(cloud, request.path, report.warnings);
    options.station_field_of_view = report.station_field_of_view;
    if (report.station_field_of_view) report.field_of_view_station = cloud.stations.front();
  }
  report.outside_view_why = outside_view_reason(report);
  // Without the exterior variant nothing reads the discs after this run:
  // its octree takes them (one copy of them fewer at a big cloud's peak).
  if (model.surfels && !request.exterior) {
    report.result = compute_cloud_occlusion(cloud, viewpoints.positions, local_openings,
                                            std::move(*model.surfels), options, progress);
  } else {
    options.surfels = model.surfels ? &*model.surfels : nullptr;
    report.result =
        compute_cloud_occlusion(cloud, viewpoints.positions, local_openings, options, progress);
  }
  job::viewpoints_to_original(report.result.viewpoints, cloud);
  report.point_model.open_surface_share = report.result.open_surface_share;

  if (request.exterior) {
    ExteriorReport exterior;
    options.blocking = exterior_mask(cloud, request.exterior_classes, request.path);
    exterior.exterior_points = static_cast<std::size_t>(
        std::count(options.blocking.begin(), options.blocking.end(), true));
    exterior.interior_points = cloud.size() - exterior.exterior_points;
    exterior.interior_exterior_ratio = interior_exterior_ratio(options.blocking);
    options.keep_escape_directions = false;
    exterior.result =
        compute_cloud_occlusion(cloud, viewpoints.positions, local_openings, options, progress);
    job::viewpoints_to_original(exterior.result.viewpoints, cloud);
    report.exterior = exterior;
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

CloudOcclusionReport run_cloud_occlusion(const CloudOcclusionRequest& request,
                                         const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  progress("loading", 0.0);
  job::LoadedCloud loaded =
      job::load_cloud(request.path, request.skip_bad_lines, std::nullopt, request.max_memory_mb);
  const StationFilterReport filtered =
      apply_station_filter(loaded.cloud, station_filter(request), request.path);
  job::name_classes(loaded.cloud, request.path, request.class_names_path);
  const std::vector<PlanarPolygon> openings = read_openings(request.polygon_path);
  const double load_seconds = job::seconds_since(start);
  progress.check_cancel();

  CloudOcclusionReport report = run_cloud_occlusion_on(
      loaded.cloud,
      job::resolve_for_cloud(request.viewpoints, loaded.cloud, request.frame, request.up), openings,
      request, progress);
  report.dropped_nan = loaded.dropped_nan;
  report.skipped_lines = loaded.skipped_lines;
  job::add_read_warnings(loaded, report.warnings);
  report.station_filter = filtered;
  report.load_seconds = load_seconds;

  if (!request.out.empty()) {
    ensure_directory(request.out);
    const std::string json_path = job::output_path(request.out, request.path, ".poc.json");
    const std::string escapes_path =
        job::output_path(request.out, request.path, ".poc.escapes.csv");
    OutputSet outputs;
    write_escapes(outputs.add(escapes_path), report.result);
    job::commit_outputs(outputs, report, json_path, {json_path, escapes_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

Json::Value to_json(const CloudOcclusionReport& report) {
  const CloudOcclusionRequest& q = report.request;
  Json::Value json = result_json(report.result, report.viewpoint_names, report.outside_view_why);
  json["job"] = "cloud_occlusion";
  json["input"] = q.path;
  json["global_shift"] = job::global_shift_json(report.shift);
  json["points"] = Json::UInt64(report.result.points);
  json["openings"] = Json::UInt64(report.openings);
  json["field_of_view"] =
      report.field_of_view ? field_of_view_json(*report.field_of_view, report.field_of_view_source)
                           : Json::Value();
  json["dropped_nan_points"] = Json::UInt64(report.dropped_nan);
  json["skipped_lines"] = Json::UInt64(report.skipped_lines);
  json["station_filter"] = station_filter_json(report.station_filter);
  json["viewpoint_source"] = report.viewpoint_source;
  json["station_field_of_view"] = job::station_field_of_view_json(
      report.station_field_of_view, report.field_of_view_station, report.result.outside_view_rays);
  if (report.exterior) {
    Json::Value exterior =
        result_json(report.exterior->result, report.viewpoint_names, report.outside_view_why);
    exterior["classes"] = to_json(q.exterior_classes);
    exterior["exterior_points"] = Json::UInt64(report.exterior->exterior_points);
    exterior["interior_points"] = Json::UInt64(report.exterior->interior_points);
    json["exterior"] = exterior;
    // JSON has no infinity: a cloud without exterior points has no ratio.
    const double ratio = report.exterior->interior_exterior_ratio;
    json["interior_exterior_ratio"] = std::isfinite(ratio) ? Json::Value(ratio) : Json::Value();
  }

  Json::Value parameters = parameters_json(cloud_occlusion_keys(), q);
  // The radius in force (measured when automatic; discs: the median), not the
  // "auto" asked for.
  parameters["point_radius"] = report.point_model.radius.radius;
  parameters["point_radius_auto"] = report.point_model.radius.automatic;
  job::stations_in_parameters(report.viewpoint_source, parameters);
  json["parameters"] = parameters;
  if (!report.frame.isNull()) json["frame"] = report.frame;
  json["point_model"] = job::point_model_json(report.point_model);
  json["point_spacing"] = job::point_radius_json(report.point_model.radius);

  json["octree"] = to_json(report.result.octree);

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  if (report.point_model.surfels) timings["surfel_seconds"] = report.point_model.surfels->seconds;
  timings["build_seconds"] = report.result.build_seconds;
  timings["trace_seconds"] = report.result.trace_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
