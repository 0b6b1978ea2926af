#pragma once
// Point clouds through Intel Embree 3, the yardsticks for our point octrees.
// Used by the benchmark only.
//
// EmbreePoints: one RTC_GEOMETRY_TYPE_SPHERE_POINT geometry, for the sphere
// octree. Embree's sphere test, like ours (core/sphere.hpp), reports the entry
// point, or the exit point when the entry lies before tnear.
//
// EmbreeDiscs: surfels (core/surfel.hpp) for the surfel octree, the oriented
// ones as one RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT geometry and the
// unoriented ones (normal zero) as one RTC_GEOMETRY_TYPE_SPHERE_POINT geometry
// of the same scene, so that both tracers see the same primitives. Embree's
// disc, like ours, is two-sided: the ray's crossing of the disc's plane, if
// within the radius of the centre.
//
// Embree's ray interval [tnear, tfar] plays the part of [t_min, t_max]; it
// cannot skip a point by id.

#include <cstddef>
#include <optional>
#include <vector>

#include "embree_common.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/sphere.hpp"
#include "occlusion/core/surfel.hpp"

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

// occluded() and version() come from EmbreeTracer.
class EmbreeDiscs : public EmbreeTracer {
 public:
  // As EmbreePoints.
  explicit EmbreeDiscs(unsigned threads);

  // (Re)builds the scene from the surfels: discs (vertex FLOAT4 x, y, z,
  // radius; normal FLOAT3) and spheres as above. A hit's primitive id is the
  // surfel's index in `surfels`. Returns the seconds from empty scene to
  // committed BVH, splitting the surfels by kind included.
  double build(const LargeVector<Surfel>& surfels);

  // hits[i] = rtcIntersect1's closest hit on rays[i] (t and surfel index), or none.
  void intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                 unsigned threads) const;

  std::size_t discs() const { return disc_ids_.size(); }
  std::size_t spheres() const { return sphere_ids_.size(); }

 private:
  // The surfel index of each primitive of the disc and sphere geometries.
  std::vector<PrimitiveId> disc_ids_, sphere_ids_;
  unsigned disc_geometry_ = RTC_INVALID_GEOMETRY_ID;
};

}  // namespace occlusion::bench
