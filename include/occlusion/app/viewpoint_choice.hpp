#pragma once
// How a job's viewpoints are chosen, shared by every job that has them:
// explicit points, a pattern (1..7, viewpoints.hpp), or num_vp points on a
// grid (grid_viewpoints). Exactly one is in force. A cloud job's default may
// defer to the cloud: its stations (scan_stations) when it records any, else
// the choice itself (stations_else).

#include <json/value.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace occlusion {

struct ViewpointChoice {
  enum class Kind { kPoints, kPattern, kGrid };
  Kind kind = Kind::kPattern;
  std::vector<Eigen::Vector3d> points;
  int pattern = 7;
  std::size_t grid_count = 9;
  // Set only by stations_else (a job's default): a cloud that records stations
  // is seen from them instead (job::resolve_for_cloud); any key given clears it.
  bool stations_first = false;
  // More viewpoints than this is a mistake, not a study (each traces its own rays).
  static constexpr std::size_t kMaxViewpoints = 10000;

  static ViewpointChoice from_points(std::vector<Eigen::Vector3d> points);
  static ViewpointChoice from_pattern(int pattern);
  static ViewpointChoice from_grid(std::size_t count);
  // The cloud's stations when it records any, else `fallback`.
  static ViewpointChoice stations_else(ViewpointChoice fallback);

  // Throws UsageError naming the option at fault.
  void validate() const;

  struct Resolved {
    // In the scene's local frame: relative to `shift`, a cloud's global shift
    // (PointCloud::shift; zero for meshes). Reports add it back.
    std::vector<Eigen::Vector3d> positions;
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    std::vector<std::string> names;
    // Where they come from, for the report: kStationsSource, or the key in
    // force ("pattern 7", "num_vp 9", "viewpoints").
    std::string source;
    // How they were placed, for the report (null when not recorded): the
    // frame used, both boxes, the up axis.
    Json::Value frame;
    // Viewpoints outside the occupied space, data that disagree with up, ...
    std::vector<std::string> warnings;
    // Per viewpoint, for a cloud (job::resolve_for_cloud): whether it was
    // warned about as outside the occupied space (a station never is).
    std::vector<bool> outside_occupied_space;
  };
  // Positions for a scene whose pattern/grid box is [lo, hi], up being
  // coordinate axis `up_axis` (grid_viewpoints).
  Resolved resolve(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int up_axis = 2) const;

  // The report's `viewpoint_source` for viewpoints that are the cloud's stations.
  static constexpr const char* kStationsSource = "stations of the file";

  // {"pattern": 7} or {"num_vp": 9} or {"viewpoints": [[x,y,z], ...]}
  Json::Value to_json() const;
};

// A viewpoint choice with a name: one configuration of the occlusion study.
struct NamedViewpointChoice {
  std::string name;
  ViewpointChoice choice;
};

}  // namespace occlusion
