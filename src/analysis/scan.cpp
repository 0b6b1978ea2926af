#include "occlusion/analysis/scan.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis_support.hpp"
#include "occlusion/analysis/banded_discs.hpp"
#include "occlusion/analysis/scan_tracer.hpp"
#include "occlusion/core/morton_order.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/sphere_octree.hpp"
#include "surfel_ray_rule.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;

// Blocks bound the per-ray memory and set how often progress and cancel are checked.
constexpr std::size_t kRaysPerBlock = std::size_t{1} << 16;
constexpr std::size_t kRayGrain = 2048;

void check_inputs(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& viewpoints,
                  const ScanOptions& options) {
  cloud.validate();
  if (cloud.size() == 0) throw std::invalid_argument("scan: the cloud has no points");
  if (viewpoints.size() > std::numeric_limits<std::uint16_t>::max()) {
    throw std::invalid_argument("scan: at most 65535 viewpoints, got " +
                                std::to_string(viewpoints.size()));
  }
  analysis_support::check_viewpoints(viewpoints, "scan");
  analysis_support::check_point_model(cloud, viewpoints, options.point_radius, options.surfels,
                                      "scan");
  if (std::isnan(options.self_tolerance) || std::isinf(options.self_tolerance)) {
    throw std::invalid_argument("scan: self_tolerance must be a finite number");
  }
}

// The segment from `from` along `direction` (t = 1 at its end) without its
// first `near_viewpoint` and its last `reach`; the empty interval [1, 0]
// (which the octree answers with "not occluded" at once) for an end too close
// to `from` to be hidden.
Ray segment_ray(const Eigen::Vector3d& from, const Eigen::Vector3d& direction,
                double near_viewpoint, double reach) {
  Ray ray;
  ray.origin = from.cast<float>();
  ray.direction = direction.cast<float>();
  const double length = direction.norm();
  if (length > near_viewpoint + reach) {
    ray.t_min = static_cast<float>(near_viewpoint / length);
    ray.t_max = static_cast<float>(1.0 - reach / length);
  } else {
    ray.t_min = 1.0f;
    ray.t_max = 0.0f;
  }
  return ray;
}

}  // namespace

Ray scan_surfel_ray(const Eigen::Vector3d& viewpoint, const Surfel& surfel, float thickness,
                    double near_viewpoint, double fixed_reach) {
  return surfel_ray_rule::ray({viewpoint.cast<float>(), static_cast<float>(near_viewpoint),
                               static_cast<float>(fixed_reach)},
                              {surfel, thickness});
}

Ray scan_shadow_ray(const Eigen::Vector3d& viewpoint, const Eigen::Vector3f& point,
                    const ScanOptions& options) {
  const double radius = options.point_radius;
  const double tolerance = options.self_tolerance < 0.0 ? 2.0 * radius : options.self_tolerance;
  // Any sphere holding the viewpoint ends within 2 r of it, so ignoring that
  // much of each ray lets a viewpoint placed inside (or on) a point see out.
  const Eigen::Vector3d direction = point.cast<double>() - viewpoint;
  return segment_ray(viewpoint, direction, 2.0 * radius, tolerance);
}

ScanTracer::ScanTracer(const PointCloud& cloud, const ScanOptions& options,
                       const Progress& progress)
    : cloud_(cloud), options_(options) {
  progress("building octree", 0.0);
  if (options.surfels) {
    near_viewpoint_ = disc_near_viewpoint(*options.surfels);
    discs_.emplace(banded_discs(*options.surfels, options.threads), options.octree, progress);
  } else {
    // Any sphere holding the viewpoint ends within 2 r of it (scan_shadow_ray).
    near_viewpoint_ = 2.0 * options.point_radius;
    spheres_.emplace(make_spheres(cloud.positions, static_cast<float>(options.point_radius)),
                     options.octree, progress);
  }
}

ScanTracer::Target ScanTracer::target(std::size_t point) const {
  if (discs_) return {options_.surfels->surfels[point], options_.surfels->thickness[point]};
  Target target;
  target.surfel.center = cloud_.positions[point];
  return target;
}

Ray ScanTracer::ray(const Eigen::Vector3d& viewpoint, const Target& target) const {
  if (discs_) {
    return scan_surfel_ray(viewpoint, target.surfel, target.thickness, near_viewpoint_,
                           options_.self_tolerance);
  }
  return scan_shadow_ray(viewpoint, target.surfel.center, options_);
}

void ScanTracer::rays(const Eigen::Vector3d& viewpoint, const Target* targets, std::size_t count,
                      Ray* out) const {
  if (!discs_) {
    for (std::size_t k = 0; k < count; ++k) out[k] = ray(viewpoint, targets[k]);
    return;
  }
  surfel_ray_rule::rays({viewpoint.cast<float>(), static_cast<float>(near_viewpoint_),
                         static_cast<float>(options_.self_tolerance)},
                        targets, count, out);
}

Ray ScanTracer::segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
  return segment_ray(from, to - from, near_viewpoint_, near_viewpoint_);
}

void ScanTracer::occluded(const Ray* rays, std::size_t count, const PrimitiveId* ignore,
                          std::uint8_t* blocked, unsigned threads, BatchOrder order) const {
  if (discs_) {
    discs_->occluded_batch(rays, count, ignore, blocked, threads, order);
  } else {
    spheres_->occluded_batch(rays, count, ignore, blocked, threads, order);
  }
}

void ScanTracer::trace(const Eigen::Vector3d& viewpoint, const std::uint32_t* points,
                       std::size_t count, std::uint8_t* seen, Ray* rays,
                       std::uint8_t* blocked) const {
  parallel_for(count, kRayGrain, options_.threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) rays[k] = ray(viewpoint, points[k]);
  });
  static_assert(sizeof(PrimitiveId) == sizeof(std::uint32_t), "point indices are primitive ids");
  occluded(rays, count, points, blocked, options_.threads, BatchOrder::kAsGiven);
  for (std::size_t k = 0; k < count; ++k) seen[k] = blocked[k] ? 0 : 1;
}

const OctreeStats& ScanTracer::stats() const {
  return discs_ ? discs_->stats() : spheres_->stats();
}

ScanResult scan_cloud(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& viewpoints,
                      const ScanOptions& options, const Progress& progress) {
  check_inputs(cloud, viewpoints, options);

  const auto start = Clock::now();
  const ScanTracer tracer(cloud, options, progress);
  ScanResult result;
  result.build_seconds = seconds_since(start);
  result.octree = tracer.stats();
  progress.check_cancel();

  const auto trace_start = Clock::now();
  const std::size_t points = cloud.size();
  const std::size_t ray_count = points * viewpoints.size();
  result.visible_count.assign(points, 0);
  result.seen_by_viewpoint.assign(viewpoints.size(), 0);
  result.first_viewpoint.assign(points, -1);
  const std::size_t block_capacity = std::min(points, kRaysPerBlock);
  std::vector<Ray> rays(block_capacity);
  std::vector<std::uint32_t> inside(block_capacity);
  std::vector<std::uint8_t> blocked(block_capacity), seen(block_capacity);
  // Viewpoint by viewpoint, the points in Morton order: a viewpoint's rays
  // share their origin and go to neighbouring points, so they are traced as
  // given, in packets that stay together down the tree, as -moc's are
  // (mesh_sample_order); the cloud's own order may be any.
  const std::vector<std::uint32_t> order = morton_order(cloud.positions, options.threads);
  progress("tracing", 0.0);
  std::size_t traced = 0;
  for (std::size_t v = 0; v < viewpoints.size(); ++v) {
    const Eigen::Vector3d& viewpoint = viewpoints[v];
    for (std::size_t first = 0; first < points; first += kRaysPerBlock) {
      const std::size_t last = std::min(points, first + kRaysPerBlock);
      // Points outside the station's window are not seen: no ray is traced.
      std::size_t count = 0;
      for (std::size_t k = first; k < last; ++k) {
        const std::uint32_t point = order[k];
        if (options.field_of_view &&
            !options.field_of_view->contains(cloud.positions[point].cast<double>() - viewpoint)) {
          ++result.outside_view_rays;
          continue;
        }
        inside[count++] = point;
      }
      tracer.trace(viewpoint, inside.data(), count, seen.data(), rays.data(), blocked.data());
      for (std::size_t k = 0; k < count; ++k) {
        if (!seen[k]) continue;
        if (result.visible_count[inside[k]] == 0) {
          result.first_viewpoint[inside[k]] = static_cast<std::int32_t>(v + 1);
        }
        ++result.visible_count[inside[k]];
        ++result.seen_by_viewpoint[v];
      }
      traced += last - first;
      progress.check_cancel();
      progress("tracing", static_cast<double>(traced) / static_cast<double>(ray_count));
    }
  }
  result.trace_seconds = seconds_since(trace_start);

  result.only_by_viewpoint.assign(viewpoints.size(), 0);
  for (std::size_t point = 0; point < points; ++point) {
    const std::uint16_t count = result.visible_count[point];
    if (count > 0) ++result.visible_points;
    if (count > 1) ++result.seen_by_several;
    if (count == 1) {
      ++result.only_by_viewpoint[static_cast<std::size_t>(result.first_viewpoint[point] - 1)];
    }
  }
  result.visible_fraction =
      static_cast<double>(result.visible_points) / static_cast<double>(points);
  progress("done", 1.0);
  return result;
}

}  // namespace occlusion
