#include "occlusion/analysis/cloud_occlusion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "analysis_support.hpp"
#include "occlusion/analysis/surface_closure.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/sphere_octree.hpp"
#include "occlusion/core/surfel_octree.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;

// Per-ray state lives only for one block, so memory does not grow with the
// number of rays; a block is still large enough to keep every core busy.
constexpr std::size_t kRaysPerBlock = std::size_t{1} << 15;
constexpr std::size_t kClassifyGrain = 1024;

enum RayClass : std::uint8_t { kHit, kThroughOpening, kOcclusion, kOutsideView };

void check_inputs(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& viewpoints,
                  const CloudOcclusionOptions& options) {
  cloud.validate();
  if (cloud.size() == 0) throw std::invalid_argument("cloud occlusion: the cloud has no points");
  analysis_support::check_viewpoints(viewpoints, "cloud occlusion");
  analysis_support::check_point_model(cloud, viewpoints, options.point_radius, options.surfels,
                                      "cloud occlusion", /*reads_thickness=*/false);
  if (options.num_rays_per_vp == 0) {
    throw std::invalid_argument("cloud occlusion: num_rays_per_vp must be > 0");
  }
  if (!std::isfinite(options.light_radius) || options.light_radius < 0.0) {
    throw std::invalid_argument("cloud occlusion: light_radius must be a finite number >= 0");
  }
  if (!options.blocking.empty() && options.blocking.size() != cloud.size()) {
    throw std::invalid_argument("cloud occlusion: the blocking mask has " +
                                std::to_string(options.blocking.size()) + " entries for " +
                                std::to_string(cloud.size()) + " points");
  }
}

// Only blocking points go into the tree: the others must not stop rays, and
// the result needs no hit ids, so they need not be mapped back. Without a
// mask the cloud's own positions make the spheres: a copy of them would live
// through the whole build (12 bytes a point at the peak).
LargeVector<Sphere> blocking_spheres(const PointCloud& cloud, const std::vector<bool>& blocking,
                                     float radius) {
  if (blocking.empty()) return make_spheres(cloud.positions, radius);
  std::vector<Eigen::Vector3f> kept;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (blocking[i]) kept.push_back(cloud.positions[i]);
  }
  return make_spheres(kept, radius);
}

// The tree of the blocking surfels: with every point blocking, the model's
// own surfels, which the tree gathers from in place (a copy of them first
// was 28 bytes a point at a big cloud's peak).
SurfelOctree blocking_surfel_tree(const LargeVector<Surfel>& surfels,
                                  const std::vector<bool>& blocking, const OctreeOptions& octree,
                                  const Progress& progress) {
  if (blocking.empty()) return SurfelOctree(surfels, octree, progress);
  LargeVector<Surfel> kept;
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    if (blocking[i]) kept.push_back(surfels[i]);
  }
  return SurfelOctree(std::move(kept), octree, progress);
}

// A ray that hit a point may still have left the room first, through an
// opening in front of that point.
RayClass classify(const Ray& ray, const std::optional<Hit>& hit,
                  const std::vector<PlanarPolygon>& openings) {
  Ray before_hit = ray;
  if (hit) before_hit.t_max = hit->t_hit;
  for (const PlanarPolygon& opening : openings) {
    if (opening.intersect(before_hit)) return kThroughOpening;
  }
  return hit ? kHit : kOcclusion;
}

}  // namespace

Ray light_source_ray(const Eigen::Vector3d& viewpoint, const Eigen::Vector3d& direction,
                     double light_radius) {
  Ray ray;
  ray.origin = (viewpoint + light_radius * direction).cast<float>();
  ray.direction = direction.cast<float>();
  ray.t_min = 0.0f;
  ray.t_max = std::numeric_limits<float>::infinity();
  return ray;
}

namespace {

template <class Shape>
CloudOcclusionResult trace(const Octree<Shape>& tree, double build_seconds, const PointCloud& cloud,
                           const std::vector<Eigen::Vector3d>& viewpoints,
                           const std::vector<PlanarPolygon>& openings,
                           const CloudOcclusionOptions& options, const Progress& progress) {
  CloudOcclusionResult result;
  result.build_seconds = build_seconds;
  result.octree = tree.stats();
  result.points = cloud.size();
  result.blocking_points = tree.size();
  progress.check_cancel();

  const auto start = Clock::now();
  const std::size_t per_view = options.num_rays_per_vp;
  const std::size_t ray_count = per_view * viewpoints.size();
  std::vector<SphereDirections> directions;
  result.viewpoints.resize(viewpoints.size());
  for (std::size_t v = 0; v < viewpoints.size(); ++v) {
    directions.emplace_back(options.sampling, per_view, options.seed, v);
    result.viewpoints[v].position = viewpoints[v];
  }

  std::vector<Ray> rays;
  std::vector<std::optional<Hit>> hits;
  std::vector<RayClass> classes;
  std::vector<std::uint8_t> outside;
  progress("tracing", 0.0);
  for (std::size_t block = 0; block < ray_count; block += kRaysPerBlock) {
    const std::size_t block_size = std::min(ray_count, block + kRaysPerBlock) - block;
    rays.resize(block_size);
    hits.resize(block_size);
    classes.resize(block_size);
    outside.resize(block_size);
    parallel_for(block_size, kClassifyGrain, options.threads, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
        const std::size_t r = block + i;
        const std::size_t v = r / per_view;
        const Eigen::Vector3d direction = directions[v](r % per_view);
        rays[i] = light_source_ray(viewpoints[v], direction, options.light_radius);
        outside[i] =
            (options.field_of_view && !options.field_of_view->contains(direction)) ||
            (options.station_field_of_view && !options.station_field_of_view->contains(direction));
        // An empty interval: the tree answers "no hit" at once.
        if (outside[i]) rays[i].t_max = -1.0f;
      }
    });
    tree.intersect_batch(rays.data(), block_size, nullptr, hits.data(), options.threads);
    parallel_for(block_size, kClassifyGrain, options.threads, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
        classes[i] = outside[i] ? kOutsideView : classify(rays[i], hits[i], openings);
      }
    });
    // Counted in ray order on this thread: escape directions keep a fixed order.
    for (std::size_t i = 0; i < block_size; ++i) {
      ViewpointRays& view = result.viewpoints[(block + i) / per_view];
      switch (classes[i]) {
        case kHit:
          ++view.hits;
          break;
        case kThroughOpening:
          ++view.through_openings;
          break;
        case kOcclusion:
          ++view.occlusion_rays;
          if (options.keep_escape_directions) {
            view.escape_directions.push_back(rays[i].direction);
          }
          break;
        case kOutsideView:
          ++view.outside_view_rays;
          break;
      }
    }
    progress.check_cancel();
    progress("tracing", static_cast<double>(block + block_size) / static_cast<double>(ray_count));
  }
  result.trace_seconds = seconds_since(start);

  const auto level = [](std::size_t occlusion_rays, std::size_t inside_view) {
    return inside_view == 0
               ? 0.0
               : static_cast<double>(occlusion_rays) / static_cast<double>(inside_view);
  };
  for (ViewpointRays& view : result.viewpoints) {
    view.rays = per_view;
    view.occlusion_level = level(view.occlusion_rays, per_view - view.outside_view_rays);
    result.rays += view.rays;
    result.hits += view.hits;
    result.through_openings += view.through_openings;
    result.occlusion_rays += view.occlusion_rays;
    result.outside_view_rays += view.outside_view_rays;
  }
  result.occlusion_level = level(result.occlusion_rays, result.rays - result.outside_view_rays);
  progress("done", 1.0);
  return result;
}

}  // namespace

namespace {

// Both entry points: `handed_over`, when set, is options.surfels's own
// surfels, which the tree takes and reorders in place.
CloudOcclusionResult compute(const PointCloud& cloud,
                             const std::vector<Eigen::Vector3d>& viewpoints,
                             const std::vector<PlanarPolygon>& openings,
                             const CloudOcclusionOptions& options, LargeVector<Surfel>* handed_over,
                             const Progress& progress) {
  check_inputs(cloud, viewpoints, options);
  if (options.surfels) {
    // From the surfels in the cloud's order, before the tree may take them.
    std::optional<ClosureRays> closure;
    if (options.blocking.empty()) closure = closure_rays(*options.surfels, options.seed);
    const auto start = Clock::now();
    progress("building octree", 0.0);
    const SurfelOctree tree = handed_over
                                  ? SurfelOctree(std::move(*handed_over), options.octree, progress)
                                  : blocking_surfel_tree(options.surfels->surfels, options.blocking,
                                                         options.octree, progress);
    CloudOcclusionResult result =
        trace(tree, seconds_since(start), cloud, viewpoints, openings, options, progress);
    if (closure) result.open_surface_share = open_surface_share(tree, *closure, options.threads);
    return result;
  }
  const auto start = Clock::now();
  progress("building octree", 0.0);
  const SphereOctree tree(
      blocking_spheres(cloud, options.blocking, static_cast<float>(options.point_radius)),
      options.octree, progress);
  return trace(tree, seconds_since(start), cloud, viewpoints, openings, options, progress);
}

}  // namespace

CloudOcclusionResult compute_cloud_occlusion(const PointCloud& cloud,
                                             const std::vector<Eigen::Vector3d>& viewpoints,
                                             const std::vector<PlanarPolygon>& openings,
                                             const CloudOcclusionOptions& options,
                                             const Progress& progress) {
  return compute(cloud, viewpoints, openings, options, nullptr, progress);
}

CloudOcclusionResult compute_cloud_occlusion(const PointCloud& cloud,
                                             const std::vector<Eigen::Vector3d>& viewpoints,
                                             const std::vector<PlanarPolygon>& openings,
                                             SurfelEstimate&& surfels,
                                             const CloudOcclusionOptions& options,
                                             const Progress& progress) {
  if (options.surfels || !options.blocking.empty()) {
    throw std::invalid_argument(
        "cloud occlusion: surfels handed over stand for options.surfels (leave it unset), "
        "with every point blocking");
  }
  CloudOcclusionOptions own = options;
  own.surfels = &surfels;
  return compute(cloud, viewpoints, openings, own, &surfels.surfels, progress);
}

double interior_exterior_ratio(const std::vector<bool>& exterior) {
  const auto outside = static_cast<std::size_t>(std::count(exterior.begin(), exterior.end(), true));
  if (outside == 0) return std::numeric_limits<double>::infinity();
  return static_cast<double>(exterior.size() - outside) / static_cast<double>(outside);
}

}  // namespace occlusion
