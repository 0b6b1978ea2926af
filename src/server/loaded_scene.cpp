#include "loaded_scene.hpp"

#include <stdexcept>

#include "occlusion/app/default_viewpoints.hpp"
#include "occlusion/app/json_output.hpp"

namespace occlusion::server {

namespace {

Json::Value bounds_json(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Json::Value bounds(Json::objectValue);
  bounds["min"] = to_json(lo);
  bounds["max"] = to_json(hi);
  return bounds;
}

}  // namespace

std::size_t LoadedScene::bytes() const {
  std::size_t total = 1024;  // the summary, roughly
  for (const auto& frame : frames) total += frame.message.size();
  if (cloud) {
    total += cloud->positions.size() * sizeof(Eigen::Vector3f) + cloud->colours.size() * 3 +
             (cloud->labels.size() + cloud->instances.size() + cloud->station_ids.size() +
              cloud->pixels.size()) *
                 4 +
             cloud->intensities.size() * sizeof(float);
  }
  if (mesh) {
    total += mesh->vertices.size() * sizeof(Eigen::Vector3d) +
             mesh->face_count() * (3 * sizeof(std::uint32_t) + sizeof(std::uint32_t));
  }
  return total;
}

std::shared_ptr<const LiveStation> LiveStationSlot::get(const std::string& key, const Build& build,
                                                        bool& built) {
  const std::lock_guard<std::mutex> lock(mutex_);
  built = false;
  if (station_ && key_ == key) return station_;
  station_.reset();  // the old model goes before the new one is built
  station_ = build();
  key_ = key;
  built = true;
  return station_;
}

std::vector<Frame> cloud_frames(const PointCloud& cloud) {
  std::vector<Frame> frames;
  const std::size_t n = cloud.size();
  // Eigen::Vector3f and std::array<uint8_t, 3> are packed value triples.
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "packed positions");
  static_assert(sizeof(std::array<std::uint8_t, 3>) == 3, "packed colours");
  frames.push_back(make_frame(FrameKind::kPositions,
                              reinterpret_cast<const float*>(cloud.positions.data()), n, 3));
  if (cloud.has_colours()) {
    frames.push_back(make_frame(FrameKind::kColours,
                                reinterpret_cast<const std::uint8_t*>(cloud.colours.data()), n, 3));
  }
  if (cloud.has_labels()) {
    frames.push_back(make_frame(FrameKind::kLabels, cloud.labels.data(), n, 1));
  }
  if (cloud.has_instances()) {
    frames.push_back(make_frame(FrameKind::kInstances, cloud.instances.data(), n, 1));
  }
  return frames;
}

std::shared_ptr<LoadedScene> cloud_scene(const PointCloud& cloud) {
  auto scene = std::make_shared<LoadedScene>();
  Json::Value& summary = scene->summary;
  summary["kind"] = "cloud";
  summary["points"] = Json::UInt64(cloud.size());
  summary["has_colours"] = cloud.has_colours();
  summary["has_labels"] = cloud.has_labels();
  summary["has_instances"] = cloud.has_instances();
  summary["class_names"] = to_json(cloud.class_names);
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  // The positions frame is the cloud's local frame; the bounds and stations,
  // like every position in JSON, are in the file's: a point of the file is a
  // position plus `shift` (PointCloud::shift).
  summary["shift"] = to_json(cloud.shift);
  summary["bounds"] =
      bounds_json(cloud.to_original(lo.cast<double>()), cloud.to_original(hi.cast<double>()));
  // Where the scanner stood (the file's stations, or a single-view frame's
  // sensor): the viewer puts its viewpoints there, as -poc and -fscan take
  // them by default.
  Json::Value stations(Json::arrayValue);
  for (const Station& station : scan_stations(cloud)) {
    Json::Value entry(Json::objectValue);
    entry["name"] = station.name;
    entry["position"] = to_json(cloud.to_original(station.frame.origin));
    stations.append(entry);
  }
  summary["stations"] = stations;
  // What -poc and -fscan take with no viewpoint given, and their warnings:
  // the viewer's markers start there, so its figures are the CLI's. A cloud
  // the jobs cannot place viewpoints on still loads (the jobs will say why).
  try {
    summary["default_viewpoints"] = default_viewpoints_json(cloud);
    summary["robust_box"] = summary["default_viewpoints"]["robust_box"];
  } catch (const std::exception&) {
    summary.removeMember("default_viewpoints");
  }
  scene->frames = cloud_frames(cloud);
  return scene;
}

std::shared_ptr<LoadedScene> mesh_scene(const TriangleMesh& mesh, const Eigen::Vector3d& shift) {
  auto scene = std::make_shared<LoadedScene>();
  Json::Value& summary = scene->summary;
  summary["kind"] = "mesh";
  summary["vertices"] = Json::UInt64(mesh.vertices.size());
  summary["faces"] = Json::UInt64(mesh.face_count());
  summary["groups"] = to_json(mesh.group_names);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  summary["bounds"] = bounds_json(lo, hi);
  summary["shift"] = to_json(shift);

  // The viewer draws in float32; the mesh is read in double, and shifted in double.
  std::vector<float> positions;
  positions.reserve(3 * mesh.vertices.size());
  for (const auto& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(v[k] - shift[k]));
  }
  static_assert(sizeof(std::array<std::uint32_t, 3>) == 12, "packed triangles");
  scene->frames.push_back(
      make_frame(FrameKind::kPositions, positions.data(), mesh.vertices.size(), 3));
  scene->frames.push_back(make_frame(FrameKind::kIndices,
                                     reinterpret_cast<const std::uint32_t*>(mesh.faces.data()),
                                     mesh.face_count(), 3));
  scene->frames.push_back(
      make_frame(FrameKind::kFaceGroups, mesh.face_group.data(), mesh.face_count(), 1));
  return scene;
}

}  // namespace occlusion::server
