// A run's scan as a sensor makes it (scan_model laser): the scene's surfaces
// scanned by the virtual scanner from the configuration's viewpoints.

#include <cmath>
#include <filesystem>

#include "job_support.hpp"
#include "occlusion/analysis/label_transfer.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/analysis/virtual_scanner.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "study_support.hpp"

namespace occlusion::job {

std::string scene_mesh_path(const std::string& scene_path) {
  namespace fs = std::filesystem;
  const fs::path scene(scene_path);
  if (fs::is_directory(scene)) {
    const fs::path folder = scene.filename().empty() ? scene.parent_path() : scene;
    return (folder / (folder.filename().string() + ".obj")).string();
  }
  fs::path mesh = scene;
  return mesh.replace_extension(".obj").string();
}

void check_scene_mesh(const StudyRequest& request, const std::string& scene_path) {
  if (request.scan_model == kIdealScan) return;
  const std::string mesh = scene_mesh_path(scene_path);
  if (!std::filesystem::is_regular_file(mesh)) {
    throw UsageError("scan_model " + request.scan_model + " scans each scene's surfaces, and " +
                     scene_path + " has none beside it: expected " + mesh +
                     " (generate_s3dis_room --mesh writes it; an OBJ whose groups name the "
                     "classes, chair_3 for a chair), or scan_model ideal");
  }
}

SensorScan sensor_scan(const StudyRequest& request, const PointCloud& scene,
                       const std::string& scene_path, const ViewpointChoice::Resolved& viewpoints,
                       const Progress& progress) {
  check_scene_mesh(request, scene_path);
  const TriangleMesh mesh = read_mesh(scene_mesh_path(scene_path));
  // The mesh is in the scene file's frame: stations go there, and the scan
  // comes back into the scene's own (shifted) frame.
  const Eigen::Vector3d up = parse_up(request.tracing.up).vector();
  std::vector<ScannerStation> stations;
  for (std::size_t s = 0; s < viewpoints.positions.size(); ++s) {
    ScannerStation station;
    station.name = "viewpoint_" + std::to_string(s + 1);
    station.position = scene.to_original(viewpoints.positions[s]);
    station.orientation = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), up);
    stations.push_back(station);
  }
  SimulationOptions options;
  options.seed = request.tracing.seed;
  options.threads = request.tracing.threads;
  options.noise = true;
  options.max_incidence_deg = request.max_incidence;
  SimulatedScan simulated;
  try {
    simulated = simulate_scan(mesh, stations, request.laser, options, progress);
  } catch (const std::invalid_argument& e) {
    throw UsageError("scan_model " + request.scan_model + ": " + e.what());
  }

  SensorScan result;
  PointCloud& scanned = result.scanned;
  const PointCloud& raw = simulated.cloud;
  scanned.shift = scene.shift;
  scanned.positions.reserve(raw.size());
  for (const Eigen::Vector3f& p : raw.positions) {
    scanned.positions.push_back(scene.to_local(raw.to_original(p.cast<double>())).cast<float>());
  }
  scanned.labels = raw.labels;
  scanned.instances = raw.instances;
  scanned.class_names = raw.class_names;
  // The scanner's camera colours each return: the colour of the scene's
  // nearest point (the segmenter reads colours; the mesh has none).
  if (scene.has_colours()) colour_from_nearest(scanned, scene, request.tracing.threads, progress);
  // A scene point counts as seen when a return lies within twice the
  // scene's spacing of it: the scan's share of the scene, as the ideal
  // scan's visible fraction is.
  result.covered.assign(scene.size(), false);
  if (scanned.size() > 0) {
    LabelTransferOptions reach;
    reach.max_distance = 2.0 * measure_point_spacing(scene, request.tracing.threads).spacing;
    reach.threads = request.tracing.threads;
    const std::vector<std::int32_t> returns(scanned.size(), 0);
    const LabelTransfer nearest =
        transfer_labels(scanned.positions, returns, scene.positions, reach, progress);
    for (std::size_t i = 0; i < scene.size(); ++i) result.covered[i] = nearest.labels[i] >= 0;
  }
  return result;
}

}  // namespace occlusion::job
