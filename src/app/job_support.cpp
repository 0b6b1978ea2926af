#include "job_support.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "occlusion/analysis/inside_solid.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/class_names_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/mesh_reader.hpp"

namespace occlusion::job {

std::string output_path(const std::string& out, const std::string& input,
                        const std::string& suffix) {
  std::filesystem::path input_path(input);
  // A folder given with a trailing slash has an empty filename: use its name.
  if (input_path.filename().empty()) input_path = input_path.parent_path();
  return (std::filesystem::path(out) / (input_path.stem().string() + suffix)).string();
}

FrameKind parse_frame(const std::string& frame) {
  try {
    return parse_frame_kind(frame);
  } catch (const std::invalid_argument& e) {
    throw KeyError("frame", std::string("is wrong: ") + e.what());
  }
}

UpAxis parse_up(const std::string& up) {
  try {
    return UpAxis::parse(up);
  } catch (const std::invalid_argument& e) {
    throw KeyError("up", std::string("is wrong: ") + e.what());
  }
}

namespace {

Json::Value box_json(const Box& box, const Eigen::Vector3d& shift) {
  Json::Value json(Json::objectValue);
  json["min"] = to_json(box.lo + shift);
  json["max"] = to_json(box.hi + shift);
  return json;
}

std::string position_text(const Eigen::Vector3d& p) {
  std::ostringstream text;
  text.precision(4);
  text << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return text.str();
}

}  // namespace

ViewpointChoice::Resolved resolve_for_cloud(const ViewpointChoice& choice, const PointCloud& cloud,
                                            const std::string& frame, const std::string& up) {
  const FrameKind kind = parse_frame(frame);
  const UpAxis up_axis = parse_up(up);
  const SceneFrame boxes = measure_scene_frame(cloud.positions);
  const Box& placement = kind == FrameKind::kRobust ? boxes.robust : boxes.bbox;
  const std::vector<Station> stations = scan_stations(cloud);
  ViewpointChoice::Resolved resolved;
  if (choice.stations_first && !stations.empty()) {
    choice.validate();
    for (const auto& station : stations) {
      resolved.positions.push_back(station.frame.origin);
      resolved.names.push_back(station.name);
    }
    resolved.source = ViewpointChoice::kStationsSource;
  } else {
    ViewpointChoice local = choice;
    for (auto& point : local.points) point = cloud.to_local(point);
    resolved = local.resolve(placement.lo, placement.hi, up_axis.axis);
  }
  resolved.shift = cloud.shift;

  resolved.frame = Json::Value(Json::objectValue);
  resolved.frame["frame"] = frame;
  resolved.frame["up"] = up_axis.name();
  resolved.frame["bbox"] = box_json(boxes.bbox, cloud.shift);
  resolved.frame["robust"] = box_json(boxes.robust, cloud.shift);
  resolved.frame["robust_quantile"] = kRobustQuantile;
  resolved.outside_occupied_space.assign(resolved.positions.size(), false);
  for (std::size_t v = 0; v < resolved.positions.size(); ++v) {
    // A scanner looks at the scene from where it stood, often outside the
    // box of what it saw from one side: no warning at a station.
    const bool at_station = std::any_of(stations.begin(), stations.end(), [&](const Station& s) {
      return (resolved.positions[v] - s.frame.origin).cwiseAbs().maxCoeff() <= 1e-6;
    });
    if (!at_station && !boxes.robust.contains(resolved.positions[v])) {
      resolved.outside_occupied_space[v] = true;
      resolved.warnings.push_back("viewpoint " + resolved.names[v] + " at " +
                                  position_text(cloud.to_original(resolved.positions[v])) +
                                  " lies outside the occupied space (the robust box from " +
                                  position_text(cloud.to_original(boxes.robust.lo)) + " to " +
                                  position_text(cloud.to_original(boxes.robust.hi)) +
                                  "): its rays measure the outside of the scene");
    }
  }
  if (resolved.source != ViewpointChoice::kStationsSource &&
      choice.kind == ViewpointChoice::Kind::kGrid) {
    if (const auto message = check_up_axis(cloud.positions, up_axis)) {
      resolved.warnings.push_back(*message);
    }
  }
  return resolved;
}

void stations_in_parameters(const std::string& viewpoint_source, Json::Value& parameters) {
  if (viewpoint_source != ViewpointChoice::kStationsSource) return;
  for (const char* key : {"viewpoints", "pattern", "num_vp"}) parameters.removeMember(key);
}

std::optional<SphericalFieldOfView> station_field_of_view(const PointCloud& cloud,
                                                          const std::string& path,
                                                          std::vector<std::string>& warnings) {
  if (!is_laser_station(cloud)) return std::nullopt;
  try {
    return measure_spherical_field_of_view(cloud);
  } catch (const std::invalid_argument& e) {
    warnings.push_back(path + " is one laser station's scan ('" + cloud.stations.front().name +
                       "') but " + e.what() + ": every direction is traced");
    return std::nullopt;
  }
}

Json::Value station_field_of_view_json(const std::optional<SphericalFieldOfView>& view,
                                       const Station& station, std::size_t outside_view_rays) {
  if (!view) return Json::Value();
  Json::Value json(Json::objectValue);
  json["station"] = station.name;
  json["grid"] = Json::Value(Json::arrayValue);
  json["grid"].append(Json::UInt64(station.frame.width));
  json["grid"].append(Json::UInt64(station.frame.height));
  json["elevation_degrees"] = Json::Value(Json::arrayValue);
  json["elevation_degrees"].append(view->elevation_lo_degrees());
  json["elevation_degrees"].append(view->elevation_hi_degrees());
  json["full_turn"] = view->full_turn;
  json["azimuth_start_degrees"] = view->azimuth_start * 180.0 / M_PI;
  json["azimuth_span_degrees"] = view->azimuth_span_degrees();
  json["outside_view_rays"] = Json::UInt64(outside_view_rays);
  return json;
}

void warn_viewpoints_inside_solids(const std::vector<ViewpointVisibility>& visibility,
                                   const ViewpointChoice::Resolved& viewpoints,
                                   std::vector<std::string>& warnings) {
  for (std::size_t v = 0; v < visibility.size(); ++v) {
    const double share = visibility[v].back_face_share;
    if (share <= kInsideBackFaceShare) continue;
    std::ostringstream message;
    message << "viewpoint " << viewpoints.names[v] << " at "
            << position_text(viewpoints.positions[v]) << ": "
            << static_cast<int>(std::lround(100.0 * share))
            << " % of its rays first hit the back of a face, so it is inside a closed solid "
               "(or the mesh's faces point away from it): move it, or check the face order";
    warnings.push_back(message.str());
  }
}

PointRadius choose_point_radius(const PointCloud& cloud, double requested, const std::string& job,
                                const std::optional<PointSpacing>& measured, unsigned threads) {
  PointRadius chosen;
  chosen.automatic = is_auto_radius(requested);
  try {
    chosen.spacing = measured ? *measured : measure_point_spacing(cloud, threads);
  } catch (const std::invalid_argument& e) {
    // Too few distinct points for a spacing: fine with an explicit radius.
    if (!chosen.automatic) {
      chosen.radius = requested;
      return chosen;
    }
    throw UsageError(std::string("--point-radius auto: ") + e.what() + "; give a radius");
  }
  const double factor = job == "-fscan" ? kScanRadiusPerSpacing : kTracingRadiusPerSpacing;
  chosen.radius = chosen.automatic ? factor * chosen.spacing.spacing : requested;
  return chosen;
}

Json::Value point_radius_json(const PointRadius& radius) {
  Json::Value json(Json::objectValue);
  json["point_radius"] = radius.radius;
  json["automatic"] = radius.automatic;
  json["spacing"] = radius.spacing.spacing;
  json["spacing_quantile_10"] = radius.spacing.quantile_10;
  json["spacing_quantile_90"] = radius.spacing.quantile_90;
  json["spacing_samples"] = Json::UInt64(radius.spacing.samples);
  json["duplicate_points_sampled"] = Json::UInt64(radius.spacing.duplicate_hits);
  return json;
}

Json::Value viewpoint_json(const std::string& name, const Eigen::Vector3d& position) {
  Json::Value json(Json::objectValue);
  json["name"] = name;
  json["position"] = to_json(position);
  return json;
}

Json::Value global_shift_json(const Eigen::Vector3d& shift) {
  return to_json(shift);
}

std::vector<PlanarPolygon> openings_in_frame(const std::vector<PlanarPolygon>& openings,
                                             const PointCloud& cloud,
                                             const std::string& polygon_path) {
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  const double reach = 10.0 * (hi - lo).cast<double>().norm();
  std::vector<PlanarPolygon> local;
  for (std::size_t k = 0; k < openings.size(); ++k) {
    std::vector<Eigen::Vector3d> boundary;
    for (const auto& corner : openings[k].vertices()) boundary.push_back(cloud.to_local(corner));
    const Eigen::Vector3d centre = local.emplace_back(boundary).origin();
    const Eigen::Vector3d outside = (lo.cast<double>() - centre)
                                        .cwiseMax(centre - hi.cast<double>())
                                        .cwiseMax(Eigen::Vector3d::Zero());
    if (outside.norm() > reach) {
      std::ostringstream message;
      message.precision(12);
      message << "opening " << k + 1 << " (centre " << openings[k].origin().transpose() << ") lies "
              << outside.norm() << " units outside the cloud's bounding box, over ten "
              << "times its diagonal: it can block no ray. Give openings in the cloud's own "
                 "coordinates, as its file holds them";
      if (cloud.shifted()) {
        message << " (the cloud is far from the origin and traced shifted by "
                << cloud.shift.transpose() << "; to coordinates given relative to that shift, "
                << "add the shift)";
      }
      throw InputError(polygon_path, 0, message.str());
    }
  }
  return local;
}

std::string cloud_extension(const std::string& format) {
  if (format == "ply" || format == "pcd") return format;
  throw KeyError("format", "must be ply or pcd, got '" + format + "'");
}

void write_json_report(const std::string& path, const Json::Value& json) {
  write_file_atomically(path, [&](std::ostream& out) { out << format_json(json) << '\n'; });
}

LoadedMesh load_mesh(const std::string& path, const Progress& progress) {
  const auto start = Clock::now();
  progress("loading", 0.0);
  LoadedMesh loaded;
  loaded.mesh = read_mesh(path, &loaded.read);
  loaded.seconds = seconds_since(start);
  progress.check_cancel();
  return loaded;
}

void warn_degenerate_faces(const std::string& path, const MeshReadReport& read,
                           std::vector<std::string>& warnings) {
  if (read.degenerate_faces == 0) return;
  const bool one = read.degenerate_faces == 1;
  warnings.push_back(
      path + ": " + std::to_string(read.degenerate_faces) +
      (one ? " degenerate face (zero area) was" : " degenerate faces (zero area) were") +
      " skipped: no area to measure, no ray hits them (first, " + read.first_degenerate + ")");
}

void add_read_warnings(const LoadedCloud& loaded, std::vector<std::string>& warnings) {
  warnings.insert(warnings.begin(), loaded.warnings.begin(), loaded.warnings.end());
}

LoadedCloud load_cloud(const std::string& path, bool skip_bad_lines,
                       const std::optional<Eigen::Vector3d>& shift, std::uint64_t max_memory_mb) {
  CloudReadOptions options;
  options.skip_bad_lines = skip_bad_lines;
  options.shift = shift;
  options.max_memory_mb = max_memory_mb != 0 ? max_memory_mb : machine_memory_mb();
  CloudReadReport report;
  LoadedCloud loaded;
  loaded.cloud = read_cloud(path, options, &report);
  loaded.dropped_nan = report.dropped_nan;
  loaded.skipped_lines = report.skipped_lines;
  loaded.rooms = report.rooms;
  loaded.unverified_order = report.unverified_order;
  loaded.annotation_order = std::move(report.annotation_order);
  loaded.warnings = std::move(report.warnings);
  return loaded;
}

void name_classes(PointCloud& cloud, const std::string& path, const std::string& class_names_path) {
  if (!class_names_path.empty()) apply_class_names_file(cloud, path, class_names_path);
}

}  // namespace occlusion::job
