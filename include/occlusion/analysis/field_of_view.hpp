#pragma once
// The field of view of a single-view frame (a depth camera's frame): the
// frustum of directions its sensor can see. Light-source rays outside it say
// nothing about occlusion (the sensor never looked there), so cloud occlusion
// counts them apart (outside_view_rays) and takes the level over the rest.
//
// The frustum is a rectangle in the sensor's image plane, tan bounds on x/z
// and y/z in the sensor frame (+z forward, PCL's convention), so a pinhole
// camera's view is held exactly, principal point off-centre included. It is
// measured from the points (the extreme x/z and y/z of the points seen from
// the sensor; for an organised W x H frame widened by half a pixel on each
// side, since the points are pixel centres) or given as full angles around
// the sensor's +z. The test is on ray directions: exact for rays from the
// sensor's position, an approximation for viewpoints elsewhere.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

struct FieldOfView {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // sensor -> cloud frame
  double x_lo = 0, x_hi = 0;  // bounds of x/z in the sensor frame
  double y_lo = 0, y_hi = 0;  // bounds of y/z

  // Whether a direction (in the cloud's frame) is inside the frustum, edges included.
  bool contains(const Eigen::Vector3d& direction) const;
  // Full angles in degrees (from the tan bounds).
  double horizontal_degrees() const;
  double vertical_degrees() const;
};

// From the frame's points and its sensor pose (cloud.sensor). Throws
// std::invalid_argument when a point is not in front of the sensor (z <= 0 in
// the sensor frame): then the cloud is no single-view frame of that sensor.
FieldOfView measure_field_of_view(const PointCloud& cloud);

// A symmetric frustum of the given full angles (degrees, in (0, 180)) around
// the sensor's +z; std::invalid_argument otherwise.
FieldOfView field_of_view_from_angles(const SensorFrame& sensor, double horizontal_degrees,
                                      double vertical_degrees);

}  // namespace occlusion
