#pragma once
// A depth frame's descriptor (`NAME.frame.json`, docs/formats.md): what a
// depth PNG cannot say itself, its intrinsics, its depth unit and its pose.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace occlusion::detail {

// The suffix that marks a descriptor, in any letter case; a `.json` alone
// would be taken for a config.
inline constexpr const char* kFrameDescriptorSuffix = ".frame.json";

struct FrameDescriptor {
  std::string name;        // the station's name: `name`, else the file name before the suffix
  std::string depth_path;  // as resolve_named_path resolves it (named_paths.hpp)
  std::optional<std::string> colour_path;
  double fx = 0, fy = 0, cx = 0, cy = 0;  // pixels
  double depth_scale = 0;                 // depth values per metre
  // Camera to world: +z forward, +y down in the camera (identity: none given).
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

// InputError naming the descriptor, the line of the field at fault and why:
// not JSON, an unknown or missing field, a value of the wrong type or out of
// range, a pose that is not a rigid motion.
FrameDescriptor read_frame_descriptor(const std::string& path);

}  // namespace occlusion::detail
