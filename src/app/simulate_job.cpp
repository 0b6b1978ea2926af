#include "occlusion/app/simulate_job.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "job_support.hpp"
#include "occlusion/analysis/label_transfer.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/sensor_model_keys.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/png_writer.hpp"

namespace occlusion {

namespace {

bool is_camera(const SimulateRequest& request) {
  return request.sensor == "camera";
}

// In double, then saturated: absurd steps must be refused, not wrap around.
std::uint64_t beams_per_station(const SimulateRequest& request) {
  const double beams = is_camera(request) ? static_cast<double>(request.camera.width) *
                                                static_cast<double>(request.camera.height)
                                          : static_cast<double>(request.laser.columns()) *
                                                static_cast<double>(request.laser.rows());
  return beams >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max()
                         : static_cast<std::uint64_t>(beams);
}

// The stations as scanned: the request's, or the centre of the mesh's box;
// a laser's vertical axis turned to `up`, a camera looking at its target.
std::vector<ScannerStation> place_stations(const TriangleMesh& mesh, const SimulateRequest& request,
                                           std::string& source) {
  std::vector<Eigen::Vector3d> positions = request.stations;
  source = "stations";
  if (positions.empty()) {
    Eigen::Vector3d lo, hi;
    mesh.bounds(lo, hi);
    positions.push_back(0.5 * (lo + hi));
    source = "the centre of the mesh's box";
  }
  const Eigen::Vector3d up = job::parse_up(request.up).vector();
  std::vector<ScannerStation> stations;
  for (std::size_t s = 0; s < positions.size(); ++s) {
    ScannerStation station;
    station.name = "station_" + std::to_string(s + 1);
    station.position = positions[s];
    if (is_camera(request)) {
      if (request.look_at.size() != positions.size()) {
        throw KeyError("look_at", "a camera needs one look_at point per station (" +
                                      std::to_string(positions.size()) + " station" +
                                      (positions.size() == 1 ? "" : "s") + ", " +
                                      std::to_string(request.look_at.size()) + " look_at)");
      }
      try {
        station.orientation = camera_looking_at(positions[s], request.look_at[s], up);
      } catch (const std::invalid_argument& e) {
        throw KeyError("look_at", station.name + ": " + e.what());
      }
    } else {
      station.orientation = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), up);
    }
    stations.push_back(station);
  }
  return stations;
}

Json::Value counts_json(const BeamCounts& counts) {
  Json::Value json(Json::objectValue);
  json["beams"] = Json::UInt64(counts.beams);
  json["points"] = Json::UInt64(counts.returns);
  json["no_return"] = Json::UInt64(counts.no_hit);
  json["out_of_range"] = Json::UInt64(counts.out_of_range);
  json["beyond_max_incidence"] = Json::UInt64(counts.grazing);
  return json;
}

// Depth values a metre: TUM's 5000 (0.2 mm) while the farthest depth fits
// 16 bits, else millimetres.
double depth_scale_for(const DepthCameraModel& camera) {
  return camera.max_depth * 5000.0 <= 65535.0 ? 5000.0 : 1000.0;
}

// One camera's scan as the camera writes it: a 16-bit depth PNG (0 where
// nothing returned) and the descriptor the depth-frame reader reads
// (docs/formats.md), its pose the station's, in the mesh's frame.
void write_camera_frame(OutputSet& outputs, const std::string& descriptor_path,
                        const std::string& png_path, const SimulateReport& report) {
  const DepthCameraModel& camera = report.request.camera;
  const PointCloud& cloud = report.scan.cloud;
  const Station& station = cloud.stations.front();
  const Eigen::Matrix3d rotation = station.frame.orientation.toRotationMatrix();
  const Eigen::Vector3d forward = rotation.col(2);
  const double scale = depth_scale_for(camera);
  std::vector<std::uint16_t> depth(camera.width * camera.height, 0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double z = (cloud.positions[i].cast<double>() - station.frame.origin).dot(forward);
    depth[cloud.pixels[i]] =
        static_cast<std::uint16_t>(std::clamp(std::round(z * scale), 1.0, 65535.0));
  }
  write_depth_png(outputs.add(png_path), camera.width, camera.height, depth);

  Json::Value descriptor(Json::objectValue);
  descriptor["depth"] = std::filesystem::path(png_path).filename().string();
  Json::Value intrinsics(Json::objectValue);
  intrinsics["fx"] = camera.fx;
  intrinsics["fy"] = camera.fy;
  intrinsics["cx"] = camera.principal_x();
  intrinsics["cy"] = camera.principal_y();
  descriptor["intrinsics"] = intrinsics;
  descriptor["depth_scale"] = scale;
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  pose.topLeftCorner<3, 3>() = rotation;
  pose.topRightCorner<3, 1>() = cloud.to_original(station.frame.origin);
  Json::Value rows(Json::arrayValue);
  for (int r = 0; r < 4; ++r) {
    Json::Value row(Json::arrayValue);
    for (int c = 0; c < 4; ++c) row.append(pose(r, c));
    rows.append(row);
  }
  descriptor["camera_to_world"] = rows;
  descriptor["name"] = station.name;
  job::write_json_report(outputs.add(descriptor_path), descriptor);
}

}  // namespace

void validate(const SimulateRequest& request) {
  if (request.path.empty()) {
    throw UsageError("no mesh given (simulate MESH or occlusion.simulate.path)");
  }
  check_keys(simulate_keys(), request);
  job::parse_up(request.up);
  job::cloud_extension(request.format);
  if (is_camera(request)) {
    if (request.camera.min_depth >= request.camera.max_depth) {
      throw KeyError("min_depth", "must be below max_depth");
    }
    if (!request.look_at.empty() && !request.stations.empty() &&
        request.look_at.size() != request.stations.size()) {
      throw KeyError("look_at", "one look_at point per station, in order (" +
                                    std::to_string(request.stations.size()) + " stations, " +
                                    std::to_string(request.look_at.size()) + " look_at)");
    }
  } else {
    const LaserScannerModel& laser = request.laser;
    if (laser.azimuth_min_deg >= laser.azimuth_max_deg ||
        laser.azimuth_max_deg - laser.azimuth_min_deg > 360.0) {
      throw KeyError("azimuth_max", "must be above azimuth_min, at most 360 degrees beyond it");
    }
    if (laser.elevation_min_deg >= laser.elevation_max_deg) {
      throw KeyError("elevation_max", "must be above elevation_min");
    }
    if (laser.min_range >= laser.max_range) throw KeyError("min_range", "must be below max_range");
    if (!request.look_at.empty()) throw KeyError("look_at", "is for sensor camera only");
  }
}

SimulateReport run_simulate_on(const TriangleMesh& mesh, const SimulateRequest& request,
                               const Progress& progress) {
  validate(request);
  SimulateReport report;
  report.request = request;
  report.stations = place_stations(mesh, request, report.station_source);
  check_memory_budget(
      simulate_memory(mesh, beams_per_station(request), report.stations.size(), request.truth),
      request.max_memory_mb);
  SimulationOptions options;
  options.seed = request.seed;
  options.threads = request.threads;
  options.noise = request.noise;
  options.max_incidence_deg = request.max_incidence;
  SensorModel sensor = request.laser;
  if (is_camera(request)) sensor = request.camera;
  try {
    report.scan = simulate_scan(mesh, report.stations, sensor, options, progress);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("simulate: ") + e.what());
  }
  if (!request.colour_from.empty()) {
    const PointCloud colours = read_cloud(request.colour_from);
    try {
      colour_from_nearest(report.scan.cloud, colours, request.threads, progress);
    } catch (const std::invalid_argument& e) {
      throw KeyError("colour_from", request.colour_from + ": " + e.what());
    }
  }
  if (report.scan.cloud.size() == 0) {
    report.warnings.push_back(
        "no beam returned: every station sees nothing within its range (are the stations "
        "inside the mesh, and max_range or max_depth large enough?)");
  }
  return report;
}

SimulateReport run_simulate(const SimulateRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  const job::LoadedMesh loaded = job::load_mesh(request.path, progress);

  SimulateReport report = run_simulate_on(loaded.mesh, request, progress);
  report.load_seconds = loaded.seconds;
  report.degenerate_faces_skipped = loaded.read.degenerate_faces;
  job::warn_degenerate_faces(request.path, loaded.read, report.warnings);
  if (!request.out.empty()) {
    ensure_directory(request.out);
    const std::string extension = "." + job::cloud_extension(request.format);
    const std::string cloud_path = job::output_path(request.out, request.path, ".sim" + extension);
    const std::string json_path = job::output_path(request.out, request.path, ".sim.json");
    OutputSet outputs;
    write_cloud(outputs.add(cloud_path), report.scan.cloud,
                request.truth ? truth_fields(report.scan) : std::vector<ScalarField>{});
    std::vector<std::string> paths{json_path, cloud_path};
    if (report.scan.cloud.sensor.organised()) {
      const std::string frame_path = job::output_path(request.out, request.path, ".sim.frame.json");
      const std::string png_path = job::output_path(request.out, request.path, ".sim.depth.png");
      write_camera_frame(outputs, frame_path, png_path, report);
      paths.push_back(frame_path);
      paths.push_back(png_path);
    }
    job::commit_outputs(outputs, report, json_path, paths, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

std::vector<ScalarField> truth_fields(const SimulatedScan& scan) {
  std::vector<ScalarField> fields;
  // Not true_nx: CloudCompare's PLY reader takes a name holding nx, ny or nz
  // for the cloud's normal, and shows no scalar field (docs/simulate.md).
  const char* names[] = {"true_x",        "true_y",        "true_z",
                         "true_normal_x", "true_normal_y", "true_normal_z"};
  for (int k = 0; k < 6; ++k) {
    ScalarField field{names[k], {}, false};
    const auto& source = k < 3 ? scan.true_points : scan.true_normals;
    field.values.reserve(source.size());
    for (const auto& v : source) field.values.push_back(v[k % 3]);
    fields.push_back(std::move(field));
  }
  ScalarField face{"face", {}, true};
  face.values.reserve(scan.faces.size());
  // Exact in float up to 2^24 faces; larger meshes' ids would round.
  for (const auto f : scan.faces) face.values.push_back(static_cast<float>(f));
  fields.push_back(std::move(face));
  return fields;
}

Json::Value to_json(const SimulateReport& report) {
  const SimulateRequest& q = report.request;
  const SimulatedScan& scan = report.scan;
  Json::Value json(Json::objectValue);
  json["job"] = "simulate";
  json["input"] = q.path;
  json["sensor"] = q.sensor;
  json["points"] = Json::UInt64(scan.cloud.size());
  json["global_shift"] = job::global_shift_json(scan.cloud.shift);
  json["degenerate_faces_skipped"] = Json::UInt64(report.degenerate_faces_skipped);
  json["beams"] = counts_json(scan.counts);
  json["station_source"] = report.station_source;
  Json::Value stations(Json::arrayValue);
  for (std::size_t s = 0; s < report.stations.size(); ++s) {
    Json::Value entry = job::viewpoint_json(report.stations[s].name, report.stations[s].position);
    const Eigen::Quaterniond& o = report.stations[s].orientation;
    Json::Value orientation(Json::arrayValue);
    for (const double value : {o.w(), o.x(), o.y(), o.z()}) orientation.append(value);
    entry["orientation_wxyz"] = orientation;
    entry["beams"] = counts_json(scan.per_station.at(s));
    stations.append(entry);
  }
  json["stations"] = stations;
  Json::Value classes(Json::arrayValue);
  std::vector<std::size_t> per_class(scan.cloud.class_names.size(), 0);
  for (const auto label : scan.cloud.labels) ++per_class[static_cast<std::size_t>(label)];
  for (std::size_t c = 0; c < per_class.size(); ++c) {
    Json::Value entry(Json::objectValue);
    entry["name"] = scan.cloud.class_names[c];
    entry["points"] = Json::UInt64(per_class[c]);
    classes.append(entry);
  }
  json["classes"] = classes;
  Json::Value parameters = parameters_json(simulate_keys(), q);
  // Only the model in force: the other sensor's keys did nothing.
  const std::vector<KeyInfo> unused =
      is_camera(q) ? key_infos(laser_scanner_keys()) : key_infos(depth_camera_keys());
  for (const auto& info : unused) parameters.removeMember(info.name);
  if (is_camera(q)) {
    parameters["cx"] = q.camera.principal_x();
    parameters["cy"] = q.camera.principal_y();
  }
  json["parameters"] = parameters;
  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  timings["build_seconds"] = scan.build_seconds;
  timings["trace_seconds"] = scan.trace_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
