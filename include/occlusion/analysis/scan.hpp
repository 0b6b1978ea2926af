#pragma once
// Fixed-viewpoint scan (-fscan): which points of a full cloud do the viewpoints
// really see? With surfels (the default model, surfel_estimation.hpp), point i
// is seen from viewpoint v if the segment between them meets no other point's
// disc, not counting hits within its own surface's reach of point i: that
// reach is (3 x the thickness of i's neighbourhood) / sin(elevation), where
// the elevation is the angle between the ray and i's disc, at least 1.5 times
// i's radius and at most twice it (2 r for an unoriented point). A disc that
// lies in i's surface meets the ray within that reach, so a surface seen at
// any positive elevation does not hide itself (nor does a noisy one, whose
// neighbours' discs stand a little in front of it: the least reach is for
// them), while an occluder farther in front of it than that still does. Hits within twice the
// median radius of the viewpoint are not counted either (a viewpoint on a point still sees).
//
// With spheres (the thesis' model), point i is seen from viewpoint v if the
// segment between them meets no other point's sphere (radius point_radius),
// not counting hits
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
#include <optional>
#include <vector>

#include "occlusion/analysis/spherical_field_of_view.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/sphere_octree.hpp"

namespace occlusion {

struct ScanOptions {
  // Spheres: every point's radius. Unused when `surfels` is set.
  double point_radius = 0.01;
  // Spheres: negative means 2 * point_radius (the default of the interface).
  double self_tolerance = -1.0;
  // Set: the points are these surfels (one per point of the cloud, owned by
  // the caller and alive through the call).
  const SurfelEstimate* surfels = nullptr;
  OctreeOptions octree = sphere_octree_options();
  unsigned threads = 0;
  // Set: a laser station's window; a point whose direction from a viewpoint
  // lies outside it is not seen from there (no ray is traced).
  std::optional<SphericalFieldOfView> field_of_view;
};

struct ScanResult {
  std::vector<std::uint16_t> visible_count;    // per point: viewpoints that see it
  std::size_t visible_points = 0;              // seen by at least one viewpoint
  double visible_fraction = 0.0;               // visible_points / points
  std::vector<std::size_t> seen_by_viewpoint;  // points each viewpoint sees
  // Per point: the number (from 1, in the viewpoints' order) of the first
  // viewpoint that sees it, -1 for none; plan's covered_by for a scan.
  std::vector<std::int32_t> first_viewpoint;
  // Per viewpoint: the points it alone sees (visible_count 1). With the
  // points seen by several and by none they make up the cloud.
  std::vector<std::size_t> only_by_viewpoint;
  std::size_t seen_by_several = 0;    // visible_count >= 2
  std::size_t outside_view_rays = 0;  // (viewpoint, point) pairs outside field_of_view
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

// The same for surfels: direction = the surfel's centre - viewpoint, over
// [near_viewpoint / |d|, 1 - reach / |d|] with the reach of the rule above
// (`thickness` is the point's), or `fixed_reach` when it is >= 0 (an explicit
// self_tolerance); the empty interval [1, 0] for a point within
// near_viewpoint + reach of the viewpoint.
Ray scan_surfel_ray(const Eigen::Vector3d& viewpoint, const Surfel& surfel, float thickness,
                    double near_viewpoint, double fixed_reach = -1.0);

}  // namespace occlusion
