#pragma once
// The octree over spheres: point clouds as seen by occlusion rays. A hit's
// primitive id is the sphere's index in the construction vector, i.e. the
// point's index when built with make_spheres.

#include <optional>

#include "occlusion/core/octree.hpp"
#include "occlusion/core/sphere.hpp"

namespace occlusion {

// The kernel the sphere octree calls.
template <class Num, class Mask>
inline Mask shape_hit(const RayComponents<Num>& ray, const Sphere& sphere, Mask active,
                      Num& t_hit) {
  return sphere_hit(ray, sphere, active, t_hit);
}

// Leaves of up to 16 points: a dense cloud puts many spheres along any ray,
// and fewer, fuller leaves cost less traversal than they add in sphere tests
// (bench_poc: -poc tracing 1.5x faster than with the triangle default of 4).
inline OctreeOptions sphere_octree_options() {
  OctreeOptions options;
  options.max_leaf_size = 16;
  return options;
}

using SphereOctree = Octree<Sphere>;
extern template class Octree<Sphere>;

}  // namespace occlusion
