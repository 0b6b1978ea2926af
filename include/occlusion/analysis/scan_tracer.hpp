#pragma once
// The -fscan rule (scan.hpp) as a reusable tracer: the cloud's octree (discs
// or spheres) built once, and "which of these points does this viewpoint
// see" asked of it for any number of viewpoints. scan_cloud traces its
// viewpoints through it, and so does scan planning (station_visibility.hpp),
// so both apply exactly one rule.

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "occlusion/analysis/scan.hpp"
#include "occlusion/core/banded_surfel_octree.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/sphere_octree.hpp"

namespace occlusion {

class ScanTracer {
 public:
  // Builds the octree of options.surfels (discs, each banded by
  // kBandSigmas (surface_noise.hpp) times its surface's measured noise) or of
  // the cloud's points as spheres of options.point_radius. `cloud` and `options` (and the surfels
  // they point to) must outlive the tracer; the caller has checked them
  // (scan_cloud's rules). Reports stage "building octree"; throws Cancelled
  // on cancel.
  ScanTracer(const PointCloud& cloud, const ScanOptions& options, const Progress& progress = {});

  // What the rule reads of a point to make its ray: its disc (for spheres,
  // its position as the centre) and its surface's thickness. A caller that
  // traces many viewpoints to the same points keeps them in the order it
  // traces them: read in that order, they stream from memory.
  struct Target {
    Surfel surfel;
    float thickness = 0.0f;
  };
  Target target(std::size_t point) const;

  // The shadow ray from `viewpoint` to a point (scan_surfel_ray or
  // scan_shadow_ray).
  Ray ray(const Eigen::Vector3d& viewpoint, std::size_t point) const {
    return ray(viewpoint, target(point));
  }
  Ray ray(const Eigen::Vector3d& viewpoint, const Target& target) const;
  // out[k] = ray(viewpoint, targets[k]) for k < count, in one tight loop:
  // many points' rays from one viewpoint (a plan's candidate).
  void rays(const Eigen::Vector3d& viewpoint, const Target* targets, std::size_t count,
            Ray* out) const;
  // The segment between two viewpoints, without what the rule ignores near a
  // viewpoint at both ends (the empty interval when they are closer than that).
  Ray segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;
  // What the rule ignores near a viewpoint: twice the median disc radius, or
  // twice point_radius for spheres.
  double near_viewpoint() const { return near_viewpoint_; }
  // The same for discs of `surfels`, before any tracer is built.
  static double disc_near_viewpoint(const SurfelEstimate& surfels) {
    return 2.0 * surfels.stats.radius_median;
  }

  // seen[k] = 1 if `viewpoint` sees point points[k], else 0, for k < count;
  // `rays` and `blocked` are scratch of at least `count` elements. The rays
  // are made and traced on options.threads threads, in the order given
  // (BatchOrder::kAsGiven): pass the points in Morton order (scan_cloud does),
  // so that rays to neighbouring points form the packets.
  void trace(const Eigen::Vector3d& viewpoint, const std::uint32_t* points, std::size_t count,
             std::uint8_t* seen, Ray* rays, std::uint8_t* blocked) const;
  // The same for rays made by the caller, ignoring ignore[k] (a point's own
  // primitive, or kNoPrimitive; ignore may be null): blocked[k] = 1 if
  // something lies on ray k. On `threads` threads (0 = all cores).
  // BatchOrder::kAsGiven for rays that are coherent already (octree.hpp).
  void occluded(const Ray* rays, std::size_t count, const PrimitiveId* ignore,
                std::uint8_t* blocked, unsigned threads,
                BatchOrder order = BatchOrder::kSortByDirection) const;

  const OctreeStats& stats() const;
  const PointCloud& cloud() const { return cloud_; }
  const ScanOptions& options() const { return options_; }

 private:
  const PointCloud& cloud_;
  const ScanOptions& options_;
  double near_viewpoint_ = 0.0;
  std::optional<BandedSurfelOctree> discs_;
  std::optional<SphereOctree> spheres_;
};

}  // namespace occlusion
