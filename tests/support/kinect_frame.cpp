#include "support/kinect_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace occlusion::testing {

namespace {

// Ray parameter where the ray from the origin along d leaves the box [lo, hi]
// (the origin is inside), and where it enters an obstacle box (infinity: never).
double exit_distance(const Eigen::Vector3d& d, const Eigen::Vector3d& lo,
                     const Eigen::Vector3d& hi) {
  double t = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] > 0) t = std::min(t, hi[a] / d[a]);
    if (d[a] < 0) t = std::min(t, lo[a] / d[a]);
  }
  return t;
}

double entry_distance(const Eigen::Vector3d& d, const Eigen::Vector3d& lo,
                      const Eigen::Vector3d& hi) {
  double near = 0.0;
  double far = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (lo[a] > 0 || hi[a] < 0) return std::numeric_limits<double>::infinity();
      continue;
    }
    double t0 = lo[a] / d[a];
    double t1 = hi[a] / d[a];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far ? near : std::numeric_limits<double>::infinity();
}

}  // namespace

PointCloud kinect_like_frame(std::size_t width, std::size_t height, double horizontal_fov_deg,
                             double depth_step) {
  // Camera frame: the room spans x in [-1.6, 2.1], y in [-1.5 (ceiling), 1.0
  // (floor)], z in [-0.5, 3.6]; a 0.6 m box stands on the floor ahead.
  const Eigen::Vector3d room_lo(-1.6, -1.5, -0.5), room_hi(2.1, 1.0, 3.6);
  const Eigen::Vector3d box_lo(-0.3, 0.4, 1.4), box_hi(0.3, 1.0, 2.0);
  const double focal =
      0.5 * static_cast<double>(width) / std::tan(0.5 * horizontal_fov_deg * M_PI / 180.0);
  PointCloud cloud;
  cloud.sensor.width = width;
  cloud.sensor.height = height;
  for (std::size_t v = 0; v < height; ++v) {
    for (std::size_t u = 0; u < width; ++u) {
      const Eigen::Vector3d d((static_cast<double>(u) + 0.5 - 0.5 * width) / focal,
                              (static_cast<double>(v) + 0.5 - 0.5 * height) / focal, 1.0);
      double t = std::min(exit_distance(d, room_lo, room_hi), entry_distance(d, box_lo, box_hi));
      // d.z() is 1, so t is the depth; a sensor reports depth in steps.
      if (depth_step > 0) t = std::round(t / depth_step) * depth_step;
      cloud.positions.push_back((t * d).cast<float>());
      cloud.pixels.push_back(static_cast<std::uint32_t>(v * width + u));
    }
  }
  return cloud;
}

}  // namespace occlusion::testing
