#pragma once
// The field of view of a terrestrial laser scanner's station (an E57 scan):
// a sibling of the pinhole FieldOfView (field_of_view.hpp). Such a scanner
// turns about its own z axis (up) and sweeps each column over a range of
// elevations, so what it can see is an elevation band, [elevation_lo,
// elevation_hi] above the scanner's xy plane, and, when it did not make a full
// turn, an azimuth window about z. Both are measured from the station's
// points, widened by half a grid step (the points are the grid's ray centres).
// Directions outside it are where the scanner never looked (under its tripod,
// past the end of a partial turn). The test is on directions: exact for rays
// from the station, the same scanner's window placed at any other viewpoint.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

struct SphericalFieldOfView {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // scanner -> cloud frame
  double elevation_lo = 0, elevation_hi = 0;  // radians, from the scanner's xy plane
  bool full_turn = true;
  // Without a full turn: azimuths (about the scanner's z, from its x axis,
  // counter-clockwise) from azimuth_start through azimuth_start + azimuth_span.
  double azimuth_start = 0, azimuth_span = 0;

  // Whether a direction (in the cloud's frame) is inside, edges included.
  bool contains(const Eigen::Vector3d& direction) const;
  double elevation_lo_degrees() const;
  double elevation_hi_degrees() const;
  double azimuth_span_degrees() const;  // 360 for a full turn
};

// A gap between neighbouring azimuths wider than this (and than four grid
// columns) is where a scanner stopped its turn, not a column without returns.
inline constexpr double kMinAzimuthGapDegrees = 10.0;

// Whether the cloud is one laser station's scan: a single station with a grid
// (width x height) that is not the cloud's single-view camera (a depth frame
// records its camera as both; field_of_view.hpp holds cameras).
bool is_laser_station(const PointCloud& cloud);

// From the cloud's points (every point is the one station's) and its
// station's pose. std::invalid_argument for a cloud that is no laser station
// (is_laser_station) or a point at the station itself.
SphericalFieldOfView measure_spherical_field_of_view(const PointCloud& cloud);

}  // namespace occlusion
