#pragma once
// The virtual scanner: a mesh scanned from stations by a real sensor's model
// (sensor_model.hpp), giving the cloud that sensor would have written, with
// each return's truth beside it. Every beam is one closest-hit ray (or
// beam_samples sub-rays) through the triangle octree; noise is drawn per beam
// from (seed, station, beam), so the same seed gives the same cloud on any
// number of threads.
//
// Labels come from the mesh's groups: a group's class is its name less a
// trailing "_<digits>" (S3DIS's chair_3 is a chair), so class_names are the
// distinct classes in order of first appearance and each point's instance is
// its group's index.

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "occlusion/analysis/sensor_model.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

using SensorModel = std::variant<LaserScannerModel, DepthCameraModel>;

// A station's pose in the mesh's frame. The orientation turns the sensor's
// own frame into the mesh's: for a laser scanner E57's scanner frame (z up),
// for a camera the camera frame (+z forward, +y down).
struct ScannerStation {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// A camera at `position` looking at `target`, its image's up towards +`up`
// (a unit axis of the mesh): the orientation a ScannerStation takes.
// std::invalid_argument when target is the position or lies along `up`.
Eigen::Quaterniond camera_looking_at(const Eigen::Vector3d& position, const Eigen::Vector3d& target,
                                     const Eigen::Vector3d& up);

struct SimulationOptions {
  std::uint64_t seed = 1;
  unsigned threads = 0;
  bool noise = true;  // false: exact returns (the truth, on the sensor's own grid)
  // Returns at a wider angle between the beam and the surface's normal are
  // lost (too little light comes back), for either sensor.
  double max_incidence_deg = 85.0;
};

// Why a beam gave no point, counted over all stations.
struct BeamCounts {
  std::size_t beams = 0;         // beams (pixels) traced
  std::size_t returns = 0;       // points kept
  std::size_t no_hit = 0;        // nothing within max range (or max depth)
  std::size_t out_of_range = 0;  // nearer than the minimum range or depth
  std::size_t grazing = 0;       // beyond the maximum incidence angle
};

struct SimulatedScan {
  // Positions relative to cloud.shift (choose_global_shift of the mesh's
  // first vertex: a mesh in UTM coordinates keeps its precision); labels,
  // instances and class_names from the groups; one station per
  // ScannerStation, each point's station_ids. A laser station's frame holds
  // its grid (columns x rows); a single camera makes an organised frame
  // (cloud.sensor, pixels).
  PointCloud cloud;
  // Per point: the surface point its beam truly hit (in the same frame), the
  // face's unit normal turned towards the station, and the face.
  std::vector<Eigen::Vector3f> true_points;
  std::vector<Eigen::Vector3f> true_normals;
  std::vector<std::uint32_t> faces;
  // Per point: its beam's grid cell (row * columns + column, or the pixel).
  std::vector<std::uint32_t> beam_cells;
  BeamCounts counts;
  std::vector<BeamCounts> per_station;
  double build_seconds = 0.0;
  double trace_seconds = 0.0;
};

// The group's class: its name less a trailing "_<digits>".
std::string class_of_group(const std::string& group_name);

// std::invalid_argument for an invalid mesh or model, no stations, a station
// that is not finite, or an incidence limit outside (0, 90] degrees; Cancelled through `progress`.
SimulatedScan simulate_scan(const TriangleMesh& mesh, const std::vector<ScannerStation>& stations,
                            const SensorModel& sensor, const SimulationOptions& options = {},
                            const Progress& progress = {});

}  // namespace occlusion
