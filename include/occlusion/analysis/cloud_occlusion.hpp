#pragma once
// Point-cloud occlusion (thesis 3.3): each point is a disc of the cloud's
// surfel model (surfel_estimation.hpp) or, as in the thesis, a sphere of
// point_radius;
// from each viewpoint a spherical light source sends num_rays_per_vp rays in
// directions uniform on the sphere. A ray that hits no point and does not
// leave through an opening is an occlusion ray; the occlusion level is the
// share of occlusion rays among all rays.
//
// Ray k of viewpoint v starts at v + light_radius * d_k and runs along the unit
// direction d_k (sphere_directions.hpp: it depends on the seed, v and k only,
// so results do not depend on the thread count). A ray that crosses an opening
// no later than its first point hit has left the room: it counts as an exit,
// not a hit. Rays are traced in blocks, so memory does not grow with the ray
// count (except the escape directions, when kept).
//
// Single-view frames (field_of_view.hpp) and laser stations
// (spherical_field_of_view.hpp): with a field of view set, a ray
// whose direction is outside it is an outside-view ray, counted apart and not
// traced, and the level is occlusion rays / (rays - outside-view rays).
//
// Exterior-structure variant (thesis 3.3.5): only the points marked in
// `blocking` stop rays (e.g. walls, floor, ceiling).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "occlusion/analysis/field_of_view.hpp"
#include "occlusion/analysis/sphere_directions.hpp"
#include "occlusion/analysis/spherical_field_of_view.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/polygon.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/sphere_octree.hpp"

namespace occlusion {

struct CloudOcclusionOptions {
  // Spheres: every point's radius. Unused when `surfels` is set.
  double point_radius = 0.01;
  // Set: the points are these surfels (one per point of the cloud, owned by
  // the caller and alive through the call).
  const SurfelEstimate* surfels = nullptr;
  std::size_t num_rays_per_vp = 30000;
  DirectionSampling sampling = DirectionSampling::kUniform;
  // Radius of the spherical light source: rays start at viewpoint + r * direction.
  double light_radius = 0.0;
  OctreeOptions octree = sphere_octree_options();
  std::uint64_t seed = 0;
  unsigned threads = 0;
  // Empty: every point blocks. Otherwise blocking[i] says whether point i does.
  std::vector<bool> blocking;
  // Keep each occlusion ray's direction per viewpoint (for the viewer).
  bool keep_escape_directions = false;
  // Set for a single-view frame: rays outside it are counted apart.
  std::optional<FieldOfView> field_of_view;
  // Set for a laser station's scan: rays outside its window are counted apart.
  std::optional<SphericalFieldOfView> station_field_of_view;
};

struct ViewpointRays {
  Eigen::Vector3d position;
  std::size_t rays = 0;
  std::size_t hits = 0;               // stopped by a point
  std::size_t through_openings = 0;   // left through an opening (and hit no point first)
  std::size_t occlusion_rays = 0;     // neither
  std::size_t outside_view_rays = 0;  // outside the field of view (when set): not traced
  // occlusion_rays / (rays - outside_view_rays); 0 when every ray is outside the view
  double occlusion_level = 0.0;
  std::vector<Eigen::Vector3f> escape_directions;  // if kept: unit directions
};

struct CloudOcclusionResult {
  double occlusion_level = 0.0;  // all occlusion rays / all rays inside the view
  std::size_t rays = 0, hits = 0, through_openings = 0, occlusion_rays = 0, outside_view_rays = 0;
  std::size_t points = 0, blocking_points = 0;
  std::vector<ViewpointRays> viewpoints;
  OctreeStats octree;
  // Discs with every point blocking: the share of the surfaces they leave
  // open (surface_closure.hpp), seeded by `seed`.
  std::optional<double> open_surface_share;
  double build_seconds = 0.0, trace_seconds = 0.0;
};

// Throws std::invalid_argument for an empty cloud, no viewpoints, a non-finite
// viewpoint, point_radius <= 0 (spheres), surfels for another cloud, num_rays_per_vp == 0, or a
// blocking mask of the wrong size; Cancelled when progress.cancel is set.
CloudOcclusionResult compute_cloud_occlusion(const PointCloud& cloud,
                                             const std::vector<Eigen::Vector3d>& viewpoints,
                                             const std::vector<PlanarPolygon>& openings,
                                             const CloudOcclusionOptions& options,
                                             const Progress& progress = {});

// The same with the disc model handed over (options.surfels unset, every
// point blocking): the octree takes the surfels and puts them in its order in
// place, where a copy of them would live beside them through its build (28
// bytes a point at a big cloud's peak). `surfels` is left with its stats and
// no surfels.
CloudOcclusionResult compute_cloud_occlusion(const PointCloud& cloud,
                                             const std::vector<Eigen::Vector3d>& viewpoints,
                                             const std::vector<PlanarPolygon>& openings,
                                             SurfelEstimate&& surfels,
                                             const CloudOcclusionOptions& options,
                                             const Progress& progress = {});

// Ray k of viewpoint v as compute_cloud_occlusion casts it, public so that the
// benchmark traces exactly the analysis' rays: for the unit direction
// d = SphereDirections(sampling, num_rays_per_vp, seed, v)(k), from
// viewpoint + light_radius * d (formed in double and rounded to float once)
// along d, over [0, infinity).
Ray light_source_ray(const Eigen::Vector3d& viewpoint, const Eigen::Vector3d& direction,
                     double light_radius);

// Interior/exterior point ratio (thesis 3.3.5): points not in `exterior` over
// points in it; +infinity when no point is exterior.
double interior_exterior_ratio(const std::vector<bool>& exterior);

}  // namespace occlusion
