#pragma once
// Point clouds through Intel Embree 3: one RTC_GEOMETRY_TYPE_SPHERE_POINT
// geometry, the yardstick for our sphere octree. Used by the benchmark only.
//
// Embree's sphere test, like ours (core/sphere.hpp), reports the entry point,
// or the exit point when the entry lies before tnear. Its ray interval
// [tnear, tfar] plays the part of [t_min, t_max]; it cannot skip a point by id.

#include <cstddef>
#include <optional>
#include <vector>

#include "embree_common.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/sphere.hpp"

namespace occlusion::bench {

// occluded() (any point on the ray) and version() come from EmbreeTracer.
class EmbreePoints : public EmbreeTracer {
 public:
  // A device whose builds use `threads` threads. Throws std::runtime_error on
  // an Embree error, or if this Embree was built without point geometry.
  explicit EmbreePoints(unsigned threads);

  // (Re)builds the scene from the spheres (vertex format FLOAT4: x, y, z,
  // radius); primitive id i is spheres[i]. Returns the seconds from empty scene
  // to committed BVH.
  double build(const LargeVector<Sphere>& spheres);

  // hits[i] = rtcIntersect1's closest hit on rays[i] (t and primID), or none.
  void intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                 unsigned threads) const;
};

}  // namespace occlusion::bench
