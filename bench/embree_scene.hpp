#pragma once
// The shadow-ray query through Intel Embree 3, the yardstick for our octree.
// Used by the benchmark only; the library never depends on Embree.
//
// Embree's ray interval [tnear, tfar] plays the part of [t_min, t_max], which
// keeps a ray off its own surface; unlike our query it cannot skip a face by id.

#include <embree3/rtcore.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion::bench {

class EmbreeScene {
 public:
  // A device whose builds use `threads` threads. Throws std::runtime_error on an Embree error.
  explicit EmbreeScene(unsigned threads);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // (Re)builds the scene as one triangle geometry, vertices rounded to float
  // as our octree rounds them. Returns the seconds from empty scene to committed BVH.
  double build(const TriangleMesh& mesh);

  // occluded[i] = 1 iff rtcOccluded1 finds anything on rays[i] within
  // [t_min, t_max]; rays are handed out in chunks to `threads` std::threads.
  void occluded(const Ray* rays, std::size_t count, std::uint8_t* occluded, unsigned threads) const;

  static std::string version() { return RTC_VERSION_STRING; }

 private:
  void check(const char* what) const;

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace occlusion::bench
