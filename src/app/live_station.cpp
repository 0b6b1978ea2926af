#include "occlusion/app/live_station.hpp"

#include <sstream>
#include <stdexcept>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/work_budget.hpp"

namespace occlusion {

namespace {

template <class... Values>
std::string joined(const Values&... values) {
  std::ostringstream out;
  out.precision(17);
  ((out << values << '\n'), ...);
  return out.str();
}

}  // namespace

std::string LiveStation::settings_key(const ScanRequest& q) {
  return joined("cloud", q.primitive, q.point_radius, q.disc_coverage, q.normal_neighbours,
                q.self_tolerance, q.octree_resolution, q.enable_acceleration, q.threads);
}

std::string LiveStation::settings_key(const MeshOcclusionRequest& q) {
  return joined("mesh", q.samples_per_unit_area, q.seed, q.octree_resolution, q.enable_acceleration,
                q.threads);
}

std::shared_ptr<const LiveStation> LiveStation::for_cloud(std::shared_ptr<const PointCloud> points,
                                                          const ScanRequest& request,
                                                          const Progress& progress) {
  const PointCloud& cloud = *points;
  check_keys(scan_keys(), request);
  const bool discs = request.primitive == "disc";
  check_memory_budget(scan_memory(cloud.size(), 1, discs), request.max_memory_mb);
  check_work_budget(scan_work(cloud.size(), 1, request.enable_acceleration), request.max_work);
  std::shared_ptr<LiveStation> station(new LiveStation());
  station->shift_ = cloud.shift;
  station->points_ = std::move(points);
  job::PointModel model = job::choose_point_model(cloud, job::point_settings(request), "-fscan",
                                                  station->warnings_, progress);
  ScanOptions options;
  options.point_radius = model.report.radius.radius;
  options.self_tolerance = request.self_tolerance;
  options.octree.min_cell_size = static_cast<float>(request.octree_resolution);
  options.octree.enable_acceleration = request.enable_acceleration;
  options.threads = request.threads;
  try {
    station->cloud_ =
        std::make_unique<CloudStationView>(cloud, std::move(model.surfels), options, progress);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  Json::Value& json = station->model_;
  json["targets"] = "points";
  json["points"] = Json::UInt64(cloud.size());
  json["point_model"] = job::point_model_json(model.report);
  json["build_seconds"] = station->cloud_->build_seconds();
  json["global_shift"] = job::global_shift_json(cloud.shift);
  return station;
}

std::shared_ptr<const LiveStation> LiveStation::for_mesh(const TriangleMesh& mesh,
                                                         const MeshOcclusionRequest& request,
                                                         const Progress& progress) {
  check_keys(mesh_occlusion_keys(), request);
  check_memory_budget(mesh_occlusion_memory(mesh, request.samples_per_unit_area, 1),
                      request.max_memory_mb);
  check_work_budget(
      mesh_occlusion_work(mesh, request.samples_per_unit_area, 1, request.enable_acceleration),
      request.max_work);
  const MeshOcclusionOptions options = mesh_occlusion_options(request);
  std::shared_ptr<LiveStation> station(new LiveStation());
  try {
    station->mesh_ = std::make_unique<MeshStationView>(mesh, options, progress);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  Json::Value& json = station->model_;
  json["targets"] = "samples";
  json["faces"] = Json::UInt64(station->mesh_->faces());
  json["samples"] = Json::UInt64(station->mesh_->samples());
  json["build_seconds"] = station->mesh_->build_seconds();
  return station;
}

LiveStationSight LiveStation::see(const Eigen::Vector3d& position,
                                  const StationLimits& limits) const {
  try {
    (void)StationLimitTest(limits);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  LiveStationSight sight;
  Json::Value& json = sight.json;
  json["position"] = to_json(position);
  Json::Value& applied = json["limits"];
  applied["max_range"] = limits.max_range;
  applied["max_incidence"] = limits.max_incidence_deg;
  applied["min_elevation"] = limits.min_elevation_deg;
  applied["max_elevation"] = limits.max_elevation_deg;
  applied["up"] = to_json(limits.up);
  try {
    if (cloud_) {
      const CloudStationSight seen = cloud_->see(position - shift_, limits);
      sight.seen.assign(seen.seen.begin(), seen.seen.end());
      const double points = static_cast<double>(std::max<std::size_t>(cloud_->size(), 1));
      json["visible_points"] = Json::UInt64(seen.seen_points);
      json["points"] = Json::UInt64(cloud_->size());
      json["visible_fraction"] = static_cast<double>(seen.seen_points) / points;
      json["trace_seconds"] = seen.trace_seconds;
    } else {
      MeshStationSight seen = mesh_->see(position, limits);
      sight.face_seen_fraction = std::move(seen.face_seen_fraction);
      json["visible_area"] = seen.visible_area;
      json["total_area"] = seen.total_area;
      json["visible_fraction"] = seen.total_area > 0.0 ? seen.visible_area / seen.total_area : 0.0;
      json["trace_seconds"] = seen.trace_seconds;
    }
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("position: ") + e.what());
  }
  return sight;
}

}  // namespace occlusion
