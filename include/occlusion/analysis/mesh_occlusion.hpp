#pragma once
// Visible-area occlusion level of a triangle mesh (thesis section 3.1).
//
// Every face is sampled (mesh_sampling.hpp). From each sample a shadow ray goes
// to each viewpoint; the sample is visible from a viewpoint if no face other
// than its own lies on the segment between them (up to a self-intersection
// tolerance of `epsilon_scale` times the scene diagonal at both ends). A sample
// is visible if any viewpoint sees it. Per face, w = visible samples / samples;
// visible area = sum of w * area; occlusion level = 1 - visible area / total area.

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion {

struct MeshSamples;  // analysis/mesh_sampling.hpp

struct MeshOcclusionOptions {
  double samples_per_unit_area = 100.0;
  OctreeOptions octree;
  std::uint64_t seed = 0;
  unsigned threads = 0;  // 0 = all cores
  // Self-intersection tolerance relative to the scene's bounding-box diagonal.
  double epsilon_scale = 1e-5;
};

struct ViewpointVisibility {
  Eigen::Vector3d position;
  double visible_area = 0.0;      // area seen from this viewpoint alone
  double visible_fraction = 0.0;  // visible_area / total_area
  // Share of its inside-solid probes whose first hit is a back face
  // (inside_solid.hpp): above kInsideBackFaceShare it is inside a solid.
  double back_face_share = 0.0;
};

struct GroupVisibility {
  std::string name;
  std::size_t faces = 0;
  double total_area = 0.0;
  double visible_area = 0.0;
  double occlusion_level = 0.0;
};

struct MeshOcclusionTimings {
  double sampling_seconds = 0.0;
  double build_seconds = 0.0;
  double trace_seconds = 0.0;
};

struct MeshOcclusionResult {
  double occlusion_level = 0.0;  // 1 - visible_area / total_area
  double visible_area = 0.0;
  double total_area = 0.0;
  std::size_t faces = 0;
  std::size_t samples = 0;
  std::size_t rays = 0;
  std::vector<ViewpointVisibility> viewpoints;
  std::vector<GroupVisibility> groups;
  // Per face: visible samples / samples, in [0, 1].
  std::vector<float> face_visible_fraction;
  OctreeStats octree;
  MeshOcclusionTimings timings;
};

// Throws std::invalid_argument for an empty mesh, no viewpoints, a non-finite
// viewpoint or invalid options; Cancelled if progress.cancel is set.
MeshOcclusionResult compute_mesh_occlusion(const TriangleMesh& mesh,
                                           const std::vector<Eigen::Vector3d>& viewpoints,
                                           const MeshOcclusionOptions& options,
                                           const Progress& progress = {});

// The two functions below are the rule compute_mesh_occlusion casts its shadow
// rays by, public so that the benchmark traces exactly the analysis' rays.

// The self-intersection tolerance in scene units: epsilon_scale times the
// diagonal of the mesh's bounding box.
double mesh_shadow_epsilon(const TriangleMesh& mesh, const MeshOcclusionOptions& options);

// The shadow ray between a sample and a viewpoint, cast FROM the viewpoint:
// direction = sample - viewpoint (t = 1 at the sample), formed in double and
// rounded to float once, over [epsilon / |d|, 1 - epsilon / |d|] so that
// `epsilon` stays clear at both ends. All rays of a viewpoint then share one
// origin, bit for bit, which is what lets the octree trace them as packets.
// False, and `ray` untouched, when the two are within 2 * epsilon of each other:
// the sample is then visible from that viewpoint without a ray. A ray longer
// than `reach` (beyond which nothing can block it) is cast from the sample
// instead and cut to that length, over [epsilon / reach, 1]. compute_mesh_occlusion passes both
// points relative to the mesh's centre and reach = twice the mesh's diagonal.
bool mesh_shadow_ray(const Eigen::Vector3d& sample, const Eigen::Vector3d& viewpoint,
                     double epsilon, Ray& ray,
                     double reach = std::numeric_limits<double>::infinity());

// The order compute_mesh_occlusion casts the rays of samples [first, first +
// count) in, each viewpoint's in turn: offsets into that range, in Morton
// order of the samples' positions. One viewpoint's rays to neighbouring
// samples then stay together down the octree, so they are traced as given
// (BatchOrder::kAsGiven) instead of sorted by direction: bench_moc's shadow
// rays took 0.5 to 0.6 of the time on AVX2, and samples in a random order
// (a mesh whose faces are, or a big face's own samples) trace as fast as in
// face order (issue 44).
std::vector<std::uint32_t> mesh_sample_order(const MeshSamples& samples, std::size_t first,
                                             std::size_t count, unsigned threads = 0);

}  // namespace occlusion
