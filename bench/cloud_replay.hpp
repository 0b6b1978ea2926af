#pragma once
// compute_cloud_occlusion's and scan_cloud's ray casting, taken apart so that
// the benchmark can time the sphere octree and Embree on the very same rays
// and check that both give the analyses' answers; plus the point cloud the
// benchmark casts them into.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "occlusion/analysis/cloud_occlusion.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion::bench {

// At least `points` area-proportional samples of the mesh's surfaces
// (sample_mesh at samples_per_unit_area_for), as a cloud of positions only.
PointCloud sample_point_cloud(const TriangleMesh& mesh, std::size_t points, std::uint64_t seed);

// The rays of compute_cloud_occlusion, viewpoint-major: ray k of viewpoint v is
// rays[v * num_rays_per_vp + k], the analysis' own light_source_ray along
// SphereDirections' d_k; traced for the closest hit, ignoring nothing.
std::vector<Ray> make_poc_rays(const std::vector<Eigen::Vector3d>& viewpoints,
                               const CloudOcclusionOptions& options);

// The analysis' occlusion level without openings: the share of rays that hit no point.
double poc_level_from_hits(const std::uint8_t* hit, std::size_t count);

struct ScanRays {
  // Viewpoint-major like the analysis, the points in Morton order as
  // scan_cloud takes them (traced as given, BatchOrder::kAsGiven): ray
  // v * points + k goes from viewpoint v to point ignore[v * points + k],
  // direction = point - viewpoint (t = 1 at the point).
  std::vector<Ray> rays;
  // The target point, which the query must not count as a blocker.
  std::vector<PrimitiveId> ignore;
  std::size_t points = 0;
  std::size_t viewpoints = 0;
};

// The shadow rays of scan_cloud, each the analysis' own scan_shadow_ray.
ScanRays make_scan_rays(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& viewpoints,
                        const ScanOptions& options);

// The shadow rays of scan_cloud with options.surfels = &surfels, each the
// analysis' own scan_surfel_ray (near the viewpoint: twice the median radius).
ScanRays make_scan_surfel_rays(const SurfelEstimate& surfels,
                               const std::vector<Eigen::Vector3d>& viewpoints,
                               const ScanOptions& options);

// The analysis' visible fraction: the share of points that some viewpoint sees.
double visible_fraction_from_flags(const ScanRays& scan, const std::uint8_t* blocked);

}  // namespace occlusion::bench
