#pragma once
// One level of the registration pyramid on PCL's classes (internal to
// analysis/; registration.cpp builds the pyramid around it). Points are in
// PCL's local frames (pcl_frame.hpp): `guess` and the answer map source-local
// to target-local coordinates.

#include <Eigen/Core>
#include <vector>

#include "occlusion/analysis/registration.hpp"

namespace occlusion::registration_detail {

struct LevelAlignment {
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  unsigned iterations = 0;
  bool converged = false;
};

LevelAlignment align_level(RegistrationMethod method, const std::vector<Eigen::Vector3f>& source,
                           const std::vector<Eigen::Vector3f>& target, const Eigen::Matrix4d& guess,
                           double voxel, double search_distance, unsigned max_iterations);

}  // namespace occlusion::registration_detail
