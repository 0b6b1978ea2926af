#pragma once
// The box the viewpoint patterns and the num_vp grid are placed on.
//
// Real scans hold stray points far outside the room (reflections, people
// walking by, points seen through windows): a few hundred points can stretch
// the bounding box of a 6 m room to 30 m, and the patterns' viewpoints then
// land outside the room. The robust frame is the box between the per-axis
// kRobustQuantile and 1 - kRobustQuantile quantiles of the points. Why
// quantiles: the surfaces that bound a room (floor, ceiling, walls) each hold
// far more than 1 % of its points, so each quantile falls inside the thickness
// of the outermost surface on that side and the box shrinks by at most that
// much, while any set of strays smaller than 1 % of the points is cut off
// however far away it is. The cost is one linear selection per axis, with no
// parameter in metres (so it works whatever the unit and density).
//
// Meshes keep their bounding box: their vertices are not samples (one big
// wall is two triangles), so vertex quantiles would cut off real walls, and a
// modelled or reconstructed mesh has no stray points.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace occlusion {

inline constexpr double kRobustQuantile = 0.01;

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
  bool contains(const Eigen::Vector3d& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
};

struct SceneFrame {
  Box bbox;    // all points
  Box robust;  // per-axis quantiles (kRobustQuantile)
};

// Throws std::invalid_argument for no points.
SceneFrame measure_scene_frame(const std::vector<Eigen::Vector3f>& points);

// Which box places the viewpoints: "robust" (default for clouds) or "bbox".
enum class FrameKind { kRobust, kBbox };
// Throws std::invalid_argument naming the allowed values.
FrameKind parse_frame_kind(const std::string& name);

}  // namespace occlusion
