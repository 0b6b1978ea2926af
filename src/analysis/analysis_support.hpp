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
#include "occlusion/core/ray.hpp"

namespace occlusion::analysis_support {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A ray nothing can block (its interval [1, 0] is empty): the slot of a
// target that needs no ray (a sample on the viewpoint) in a block traced whole.
inline Ray unblockable_ray(const Eigen::Vector3d& from) {
  Ray ray;
  ray.origin = from.cast<float>();
  ray.direction = Eigen::Vector3f::UnitX();
  ray.t_min = 1.0f;
  ray.t_max = 0.0f;
  return ray;
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

// What check_float_precision measures against: the length rays must
// resolve (a cloud's point radius, a mesh's diagonal), the point distances
// are measured from, and the scene's name.
struct PrecisionFrame {
  double length = 0.0;
  std::string length_name;  // "point_radius"
  std::string origin;       // "the origin of the cloud's local frame (...)"
  std::string scene;        // "cloud", "mesh"
};

// Scenes are traced in float, in a local frame (the readers subtract a global
// shift from clouds far from the origin, PointCloud::shift; mesh occlusion
// traces around the mesh's centre): at a distance d from that frame's origin,
// neighbouring floats are d * 2^-23 apart. Throws std::invalid_argument when
// the scene or a viewpoint is so far out that this spacing exceeds a quarter
// of frame.length. For a cloud that length is point_radius: rays pass between
// the spheres they should hit (a viewpoint at 1e20 saw through closed walls).
// For a mesh it is its diagonal: from there the whole mesh lies within a few
// float steps of one direction, and rays that graze a face decide by rounding
// whether they hit (a viewpoint 1e10 from a box answered 0.8171, not 0.8837).
// After the shift this is a scene whose own extent is too large for float, or
// a viewpoint far from the scene.
inline void check_float_precision(const Eigen::Vector3f& scene_lo, const Eigen::Vector3f& scene_hi,
                                  const std::vector<Eigen::Vector3d>& viewpoints,
                                  const PrecisionFrame& frame, const std::string& analysis) {
  constexpr double kFloatSpacing = 1.0 / (1 << 23);
  const double limit = 0.25 * frame.length / kFloatSpacing;
  const auto refuse = [&](const std::string& what, double distance, const std::string& fix) {
    throw std::invalid_argument(
        analysis + ": " + what + " " + std::to_string(distance) + " units from " + frame.origin +
        ", where float coordinates are " + std::to_string(distance * kFloatSpacing) +
        " units apart, too coarse for " + frame.length_name + " " + std::to_string(frame.length) +
        "; everything must lie within " + std::to_string(limit) + " units of it: " + fix);
  };
  const double scene_extent = std::max(scene_lo.cast<double>().cwiseAbs().maxCoeff(),
                                       scene_hi.cast<double>().cwiseAbs().maxCoeff());
  if (scene_extent > limit) {
    refuse("the " + frame.scene + " reaches", scene_extent,
           "split the " + frame.scene +
               " into smaller tiles, or shift its coordinates so it starts near the origin");
  }
  for (const auto& viewpoint : viewpoints) {
    const double distance = viewpoint.cwiseAbs().maxCoeff();
    if (distance > limit) {
      refuse("a viewpoint lies", distance,
             "place viewpoints near the " + frame.scene + ", in the " + frame.scene +
                 " file's own coordinates");
    }
  }
}

// The point model's checks, for both cloud analyses: surfels (when given)
// hold one disc per point, and one thickness per point where the analysis
// reads it, and the radius traced with (the spheres', or the surfels' 10th
// percentile) is positive and fine enough for float at the cloud's and
// viewpoints' distances (check_float_precision).
inline void check_point_model(const PointCloud& cloud,
                              const std::vector<Eigen::Vector3d>& viewpoints, double point_radius,
                              const SurfelEstimate* surfels, const std::string& analysis,
                              bool reads_thickness = true) {
  double radius = point_radius;
  if (surfels) {
    if (surfels->surfels.size() != cloud.size() ||
        (reads_thickness && surfels->thickness.size() != cloud.size()) ||
        (!surfels->noise.sigma.empty() && surfels->noise.sigma.size() != cloud.size())) {
      throw std::invalid_argument(analysis + ": " + std::to_string(surfels->surfels.size()) +
                                  " surfels for " + std::to_string(cloud.size()) + " points");
    }
    radius = surfels->stats.radius_quantile_10;
  }
  check_positive(radius, "point_radius", analysis);
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  check_float_precision(lo, hi, viewpoints,
                        {radius, "point_radius",
                         "the origin of the cloud's local frame (its coordinates minus its global "
                         "shift)",
                         "cloud"},
                        analysis);
}

}  // namespace occlusion::analysis_support
