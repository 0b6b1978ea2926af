#pragma once
// How closed a cloud's surfaces are under its disc model: the share of rays
// crossing a surface that meet none of its discs.
//
// Estimated at sample points of the cloud (every k-th oriented point): a short
// ray through the point, along a random direction within 60 degrees of its
// normal, from half its radius in front of the surface to half its radius
// behind, that does not count the point's own disc. Which share of the others'
// union leaves a sample point open is which share leaves a random spot of the
// surface open (for points sampled at random, Slivnyak's theorem), so no
// surface spot need be known. Directions are drawn from the seed.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/surfel_octree.hpp"

namespace occlusion {

inline constexpr std::size_t kClosureSamples = 20000;

// The sample rays, each with the point whose disc it does not count. Made
// from the surfels in the cloud's order, so that a caller can make them
// before handing the surfels to an octree that reorders them.
struct ClosureRays {
  std::vector<Ray> rays;
  std::vector<PrimitiveId> own;
};
ClosureRays closure_rays(const SurfelEstimate& estimate, std::uint64_t seed,
                         std::size_t samples = kClosureSamples);

// `tree` holds the estimate's surfels (primitive id = point index). Returns
// 0 when there are no rays (no point is oriented).
double open_surface_share(const SurfelOctree& tree, const ClosureRays& closure,
                          unsigned threads = 0);

}  // namespace occlusion
