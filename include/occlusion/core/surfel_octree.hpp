#pragma once
// The octree over surfels: point clouds as discs (surfel.hpp). A hit's
// primitive id is the surfel's index in the construction vector, i.e. the
// point's index when built with make_surfels.

#include "occlusion/core/octree.hpp"
#include "occlusion/core/surfel.hpp"

namespace occlusion {

// The kernel the surfel octree calls.
template <class Num, class Mask>
inline Mask shape_hit(const RayComponents<Num>& ray, const Surfel& surfel, Mask active,
                      Num& t_hit) {
  return surfel_hit(ray, surfel, active, t_hit);
}

// Leaves of up to 16 surfels, as for spheres (sphere_octree_options): a dense
// cloud puts many points along any ray.
inline OctreeOptions surfel_octree_options() {
  OctreeOptions options;
  options.max_leaf_size = 16;
  return options;
}

using SurfelOctree = Octree<Surfel>;
extern template class Octree<Surfel>;

}  // namespace occlusion
