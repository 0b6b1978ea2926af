#pragma once
// The octree over spheres: point clouds as seen by occlusion rays. A hit's
// primitive id is the sphere's index in the construction vector, i.e. the
// point's index when built with make_spheres.

#include <optional>

#include "occlusion/core/octree.hpp"
#include "occlusion/core/sphere.hpp"

namespace occlusion {

// The kernel the sphere octree calls.
inline std::optional<float> intersect_shape(const Ray& ray, float direction_length,
                                            const Sphere& sphere) {
  return intersect_sphere(ray, direction_length, sphere);
}

using SphereOctree = Octree<Sphere>;
extern template class Octree<Sphere>;

}  // namespace occlusion
