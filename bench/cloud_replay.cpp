#include "cloud_replay.hpp"

#include "moc_replay.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/sphere_directions.hpp"
#include "occlusion/core/morton_order.hpp"

namespace occlusion::bench {

PointCloud sample_point_cloud(const TriangleMesh& mesh, std::size_t points, std::uint64_t seed) {
  const MeshSamples samples = sample_mesh(mesh, samples_per_unit_area_for(mesh, points), seed);
  PointCloud cloud;
  cloud.positions.reserve(samples.size());
  for (const Eigen::Vector3d& p : samples.points) cloud.positions.push_back(p.cast<float>());
  return cloud;
}

std::vector<Ray> make_poc_rays(const std::vector<Eigen::Vector3d>& viewpoints,
                               const CloudOcclusionOptions& options) {
  const std::size_t per_view = options.num_rays_per_vp;
  std::vector<Ray> rays(per_view * viewpoints.size());
  for (std::size_t v = 0; v < viewpoints.size(); ++v) {
    const SphereDirections directions(options.sampling, per_view, options.seed, v);
    for (std::size_t k = 0; k < per_view; ++k) {
      rays[v * per_view + k] = light_source_ray(viewpoints[v], directions(k), options.light_radius);
    }
  }
  return rays;
}

double poc_level_from_hits(const std::uint8_t* hit, std::size_t count) {
  std::size_t misses = 0;
  for (std::size_t i = 0; i < count; ++i) misses += hit[i] ? 0 : 1;
  return count > 0 ? static_cast<double>(misses) / static_cast<double>(count) : 0.0;
}

namespace {

// ScanRays to the points at `positions`, ray v * points + k =
// make_ray(viewpoints[v], i) for the k-th point i in Morton order.
template <class MakeRay>
ScanRays make_rays(const std::vector<Eigen::Vector3f>& positions,
                   const std::vector<Eigen::Vector3d>& viewpoints, const MakeRay& make_ray) {
  ScanRays out;
  out.points = positions.size();
  out.viewpoints = viewpoints.size();
  out.rays.resize(out.points * out.viewpoints);
  out.ignore.resize(out.rays.size());
  const std::vector<std::uint32_t> order = morton_order(positions);
  for (std::size_t v = 0; v < out.viewpoints; ++v) {
    for (std::size_t k = 0; k < out.points; ++k) {
      out.rays[v * out.points + k] = make_ray(viewpoints[v], order[k]);
      out.ignore[v * out.points + k] = order[k];
    }
  }
  return out;
}

}  // namespace

ScanRays make_scan_rays(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& viewpoints,
                        const ScanOptions& options) {
  return make_rays(cloud.positions, viewpoints,
                   [&](const Eigen::Vector3d& viewpoint, std::size_t i) {
                     return scan_shadow_ray(viewpoint, cloud.positions[i], options);
                   });
}

ScanRays make_scan_surfel_rays(const SurfelEstimate& surfels,
                               const std::vector<Eigen::Vector3d>& viewpoints,
                               const ScanOptions& options) {
  const double near_viewpoint = 2.0 * surfels.stats.radius_median;
  std::vector<Eigen::Vector3f> centers;
  centers.reserve(surfels.surfels.size());
  for (const Surfel& surfel : surfels.surfels) centers.push_back(surfel.center);
  return make_rays(centers, viewpoints, [&](const Eigen::Vector3d& viewpoint, std::size_t i) {
    return scan_surfel_ray(viewpoint, surfels.surfels[i], surfels.thickness[i], near_viewpoint,
                           options.self_tolerance);
  });
}

double visible_fraction_from_flags(const ScanRays& scan, const std::uint8_t* blocked) {
  std::vector<std::uint8_t> seen(scan.points, 0);
  for (std::size_t r = 0; r < scan.rays.size(); ++r) {
    if (!blocked[r]) seen[scan.ignore[r]] = 1;
  }
  std::size_t visible = 0;
  for (const std::uint8_t s : seen) visible += s;
  return scan.points > 0 ? static_cast<double>(visible) / static_cast<double>(scan.points) : 0.0;
}

}  // namespace occlusion::bench
