#pragma once
// TEMPORARY STAND-IN, to be replaced by io/pose_file.hpp (issue 42, branch
// i42scene) when it lands: the register job reads its initial pose and
// writes the refined one here, in the one format this reads, a 4 x 4 matrix
// in rows (16 numbers, last row 0 0 0 1). Its names follow pose_file.hpp's so
// the switch is an include and a namespace.

#include <Eigen/Geometry>
#include <string>

namespace occlusion::pose_stand_in {

struct ScanPose {
  Eigen::Isometry3d scan_to_scene = Eigen::Isometry3d::Identity();
};

inline const char* pose_format_name(const ScanPose&) {
  return "matrix";
}
// InputError naming the file for anything but 16 numbers forming a rigid motion.
ScanPose read_pose_file(const std::string& path);
// Atomically; OutputError if it cannot be written.
void write_pose_file(const std::string& path, const ScanPose& pose);

}  // namespace occlusion::pose_stand_in
