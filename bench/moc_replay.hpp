#pragma once
// compute_mesh_occlusion's ray casting, taken apart so that the benchmark can
// time the octree and Embree on the very same shadow rays and check that both
// give the analysis' answer.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion::bench {

struct ShadowRays {
  // Sample-major like the analysis: pair (sample s, viewpoint v) is slot
  // s * viewpoints + v. A sample within 2 eps of a viewpoint is trivially
  // visible from it and gets no ray, so rays[i] serves slot[i].
  std::vector<Ray> rays;
  // The face each ray starts on, which the query must not count as a blocker.
  std::vector<PrimitiveId> ignore;
  std::vector<std::size_t> slot;
  std::size_t samples = 0;
  std::size_t viewpoints = 0;
};

// Each ray is the analysis' own (mesh_shadow_ray), viewpoint by viewpoint in
// its order (mesh_sample_order), to be traced as given (BatchOrder::kAsGiven)
// as the analysis traces them; pass mesh_shadow_epsilon.
ShadowRays make_shadow_rays(const MeshSamples& samples,
                            const std::vector<Eigen::Vector3d>& viewpoints, double epsilon);

// The analysis' reduction of per-ray flags (occluded[i] for shadow.rays[i])
// to the occlusion level: a sample is visible if any viewpoint sees it.
double occlusion_level_from_flags(const TriangleMesh& mesh, const MeshSamples& samples,
                                  const ShadowRays& shadow, const std::uint8_t* occluded);

// Per face, the share of its samples that some viewpoint sees, from
// seen[s * viewpoints + v] (sample s seen from viewpoint v); 0 for a face
// without samples.
std::vector<double> face_visible_fractions(const TriangleMesh& mesh, const MeshSamples& samples,
                                           std::size_t viewpoints,
                                           const std::vector<std::uint8_t>& seen);

// 1 - sum(area x visible fraction) / total area, as compute_mesh_occlusion reduces faces.
double occlusion_level_of_faces(const TriangleMesh& mesh, const std::vector<double>& fractions);

// A samples_per_unit_area for which sample_mesh yields at least `samples`
// samples: samples / total area if that suffices, else the smallest density
// above it that does (within 1e-9 relative).
double samples_per_unit_area_for(const TriangleMesh& mesh, std::size_t samples);

}  // namespace occlusion::bench
