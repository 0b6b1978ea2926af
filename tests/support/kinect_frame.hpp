#pragma once
// A depth camera's organised frame of a scene whose answer is known.

#include <cstddef>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion::testing {

// A Kinect-like organised depth frame of a room corner with a box on the
// floor, in the camera frame (sensor at the origin, +z forward, +y down, floor
// 1 m below the sensor): pixel (u, v) of a width x height image with the given
// horizontal field of view (degrees) holds the first surface along its ray.
// Every pixel sees a surface, so a scan from the origin must keep every point.
// depth_step > 0 rounds each depth (z) to a multiple of it, as a sensor does.
// Each point's pixel is in PointCloud::pixels, as the readers give it.
PointCloud kinect_like_frame(std::size_t width, std::size_t height, double horizontal_fov_deg,
                             double depth_step = 0.0);

}  // namespace occlusion::testing
