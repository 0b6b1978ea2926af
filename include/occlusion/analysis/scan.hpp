#pragma once
// Fixed-viewpoint scan (-fscan): which points of a full cloud do the viewpoints
// really see? Point i is seen from viewpoint v if the segment between them
// meets no other point's sphere (radius point_radius), not counting hits
// within self_tolerance of point i (its neighbours on the same surface would
// otherwise hide it) nor within 2 * point_radius of the viewpoint (every sphere
// that holds the viewpoint ends there, so a viewpoint placed inside a point's
// sphere, or on a point, still sees). A point closer to the viewpoint than
// 2 * point_radius + self_tolerance is seen.
//
// On a densely sampled surface a neighbour's sphere reaches the ray up to
// point_radius / sin(elevation) from the point, so a surface seen at an
// elevation below asin(point_radius / self_tolerance) hides itself: 30 degrees
// with the default tolerance.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "occlusion/core/octree.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/sphere_octree.hpp"

namespace occlusion {

struct ScanOptions {
  double point_radius = 0.01;
  // Negative: 2 * point_radius (the default of the interface).
  double self_tolerance = -1.0;
  OctreeOptions octree = sphere_octree_options();
  unsigned threads = 0;
};

struct ScanResult {
  std::vector<std::uint16_t> visible_count;    // per point: viewpoints that see it
  std::size_t visible_points = 0;              // seen by at least one viewpoint
  double visible_fraction = 0.0;               // visible_points / points
  std::vector<std::size_t> seen_by_viewpoint;  // points each viewpoint sees
  OctreeStats octree;
  double build_seconds = 0.0, trace_seconds = 0.0;
};

// Throws std::invalid_argument for an empty cloud, no or non-finite viewpoints,
// point_radius <= 0, or more than 65535 viewpoints; Cancelled on cancel.
ScanResult scan_cloud(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& viewpoints,
                      const ScanOptions& options, const Progress& progress = {});

// The shadow ray scan_cloud casts from a viewpoint to a point, public so that
// the benchmark traces exactly the analysis' rays: direction = point - viewpoint
// (t = 1 at the point), formed in double and rounded to float once, over
// [2 r / |d|, 1 - tolerance / |d|] with r = point_radius and tolerance =
// self_tolerance (or its default). A point within 2 r + tolerance of the
// viewpoint gets the empty interval [1, 0], which the octree answers with
// "not occluded" at once.
Ray scan_shadow_ray(const Eigen::Vector3d& viewpoint, const Eigen::Vector3f& point,
                    const ScanOptions& options);

}  // namespace occlusion
