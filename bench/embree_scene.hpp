#pragma once
// The shadow-ray query through Intel Embree 3, the yardstick for our octree.
// Used by the benchmark only; the library never depends on Embree.
//
// Embree's ray interval [tnear, tfar] plays the part of [t_min, t_max], which
// keeps a ray off its own surface; unlike our query it cannot skip a face by id.

#include "embree_common.hpp"
#include "occlusion/core/mesh.hpp"

namespace occlusion::bench {

// occluded() and version() come from EmbreeTracer.
class EmbreeScene : public EmbreeTracer {
 public:
  // A device whose builds use `threads` threads. Throws std::runtime_error on an Embree error.
  explicit EmbreeScene(unsigned threads) : EmbreeTracer(threads) {}

  // (Re)builds the scene as one triangle geometry, vertices rounded to float
  // as our octree rounds them. Returns the seconds from empty scene to committed BVH.
  double build(const TriangleMesh& mesh);

  // hits[i] = rtcIntersect1's closest hit on rays[i] (t and face index), or none.
  void intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                 unsigned threads) const;
};

}  // namespace occlusion::bench
