#pragma once
// Pieces every analysis shares (internal to analysis/): timing and the
// argument checks each one makes at its API edge.

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/point_cloud.hpp"

namespace occlusion::analysis_support {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Throws std::invalid_argument("<analysis>: ...") for no viewpoints or a non-finite one.
inline void check_viewpoints(const std::vector<Eigen::Vector3d>& viewpoints,
                             const std::string& analysis) {
  if (viewpoints.empty()) throw std::invalid_argument(analysis + ": no viewpoints given");
  for (const auto& viewpoint : viewpoints) {
    if (!viewpoint.allFinite()) {
      throw std::invalid_argument(analysis + ": a viewpoint is not finite");
    }
  }
}

// Throws unless value is finite and > 0.
inline void check_positive(double value, const std::string& name, const std::string& analysis) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(analysis + ": " + name + " must be a finite number > 0");
  }
}

// Clouds are traced in float, in their local frame (the readers subtract a
// global shift from clouds far from the origin, PointCloud::shift): at a
// distance d from that frame's origin, neighbouring floats are d * 2^-23
// apart. Throws std::invalid_argument when a point or viewpoint is so far out
// that this spacing exceeds a quarter of point_radius, where rays pass between
// the spheres they should hit (a viewpoint at 1e20 saw through closed walls).
// After the shift this is a cloud whose own extent is too large for float at
// its radius, or a viewpoint far from the cloud.
inline void check_float_precision(const Eigen::Vector3f& cloud_lo, const Eigen::Vector3f& cloud_hi,
                                  const std::vector<Eigen::Vector3d>& viewpoints,
                                  double point_radius, const std::string& analysis) {
  constexpr double kFloatSpacing = 1.0 / (1 << 23);
  const double limit = 0.25 * point_radius / kFloatSpacing;
  const auto refuse = [&](const std::string& what, double distance, const std::string& fix) {
    throw std::invalid_argument(
        analysis + ": " + what + " " + std::to_string(distance) +
        " units from the origin of the cloud's local frame (its coordinates minus its global "
        "shift), where float coordinates are " +
        std::to_string(distance * kFloatSpacing) + " units apart, too coarse for point_radius " +
        std::to_string(point_radius) + "; everything must lie within " + std::to_string(limit) +
        " units of it: " + fix);
  };
  const double cloud_extent = std::max(cloud_lo.cast<double>().cwiseAbs().maxCoeff(),
                                       cloud_hi.cast<double>().cwiseAbs().maxCoeff());
  if (cloud_extent > limit) {
    refuse("the cloud reaches", cloud_extent,
           "split the cloud into smaller tiles, or shift its coordinates so it starts near the "
           "origin");
  }
  for (const auto& viewpoint : viewpoints) {
    const double distance = viewpoint.cwiseAbs().maxCoeff();
    if (distance > limit) {
      refuse("a viewpoint lies", distance,
             "place viewpoints near the cloud, in the cloud file's own coordinates");
    }
  }
}

// The point model's checks, for both cloud analyses: surfels (when given)
// hold one disc and one thickness per point, and the radius traced with (the
// spheres', or the surfels' 10th percentile) is positive and fine enough for
// float at the cloud's and viewpoints' distances (check_float_precision).
inline void check_point_model(const PointCloud& cloud,
                              const std::vector<Eigen::Vector3d>& viewpoints, double point_radius,
                              const SurfelEstimate* surfels, const std::string& analysis) {
  double radius = point_radius;
  if (surfels) {
    if (surfels->surfels.size() != cloud.size() || surfels->thickness.size() != cloud.size()) {
      throw std::invalid_argument(analysis + ": " + std::to_string(surfels->surfels.size()) +
                                  " surfels for " + std::to_string(cloud.size()) + " points");
    }
    radius = surfels->stats.radius_quantile_10;
  }
  check_positive(radius, "point_radius", analysis);
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  check_float_precision(lo, hi, viewpoints, radius, analysis);
}

}  // namespace occlusion::analysis_support
