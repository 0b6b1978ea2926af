#pragma once
// What the two Embree yardsticks (embree_scene.hpp: triangles, embree_points.hpp:
// sphere points) share, so that both measure Embree the same way: our rays in
// Embree's form, the threads the rays are traced on, and EmbreeTracer (one
// device, its one single-geometry scene, the any-hit query). Used by the
// benchmark only; the library never depends on Embree.

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "occlusion/core/hit.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion::bench {

// Small enough to balance rays of uneven cost, large enough that the shared
// counter is rarely contended.
inline constexpr std::size_t kEmbreeRayChunk = 4096;

// Embree's interval [tnear, tfar] is our [t_min, t_max]; all geometry masks on.
// Inline: it runs once per traced ray.
inline RTCRay to_embree(const Ray& in) {
  RTCRay ray;
  ray.org_x = in.origin.x();
  ray.org_y = in.origin.y();
  ray.org_z = in.origin.z();
  ray.tnear = in.t_min;
  ray.dir_x = in.direction.x();
  ray.dir_y = in.direction.y();
  ray.dir_z = in.direction.z();
  ray.time = 0.0f;
  ray.tfar = in.t_max;
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

// Calls body(context, i) for every i < count, in chunks handed out to `threads`
// std::threads, each with its own intersect context.
template <class Body>
void for_each_ray(std::size_t count, unsigned threads, const Body& body) {
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t begin; (begin = next.fetch_add(kEmbreeRayChunk)) < count;) {
      const std::size_t end = std::min(count, begin + kEmbreeRayChunk);
      for (std::size_t i = begin; i < end; ++i) body(context, i);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(1u, threads); ++t) pool.emplace_back(work);
  for (std::thread& thread : pool) thread.join();
}

// A device whose builds use `threads` threads, the one scene built on it, and
// the any-hit query; EmbreeScene and EmbreePoints add the geometry.
class EmbreeTracer {
 public:
  // Throws std::runtime_error if the device cannot be created.
  explicit EmbreeTracer(unsigned threads);
  ~EmbreeTracer();
  EmbreeTracer(const EmbreeTracer&) = delete;
  EmbreeTracer& operator=(const EmbreeTracer&) = delete;

  // occluded[i] = 1 iff rtcOccluded1 finds anything on rays[i] within
  // [t_min, t_max]; rays are handed out in chunks to `threads` std::threads.
  // Throws std::logic_error before the first build.
  void occluded(const Ray* rays, std::size_t count, std::uint8_t* occluded, unsigned threads) const;

  // The same over rays made as they are traced, the way a program that does
  // not keep millions of rays would: make_ray(i, ray) fills ray i and returns
  // true, or returns false when there is no ray to trace (occluded[i] = 0).
  template <class MakeRay>
  void occluded_made(std::size_t count, const MakeRay& make_ray, std::uint8_t* occluded,
                     unsigned threads) const {
    if (!scene_) throw std::logic_error("embree: occluded before build");
    for_each_ray(count, threads, [&](RTCIntersectContext& context, std::size_t i) {
      Ray made;
      if (!make_ray(i, made)) {
        occluded[i] = 0;
        return;
      }
      RTCRay ray = to_embree(made);
      rtcOccluded1(scene_, &context, &ray);
      // Embree marks an occluded ray by setting tfar to -infinity.
      occluded[i] = ray.tfar < 0.0f ? 1 : 0;
    });
  }

  static std::string version() { return RTC_VERSION_STRING; }

 protected:
  RTCDevice device() const { return device_; }
  // Null before the first build.
  RTCScene scene() const { return scene_; }

  // Replaces the scene with one geometry of `type`, whose buffers fill(geometry)
  // sets. Returns the seconds from empty scene to committed BVH.
  template <class Fill>
  double build_scene(RTCGeometryType type, const Fill& fill) {
    return build_geometries([&](const auto& add) { add(type, fill); });
  }

  // Replaces the scene with the geometries add_all(add) adds: add(type, fill)
  // makes a geometry of `type`, lets fill(geometry) set its buffers, attaches
  // it and returns its geomID. Returns the seconds from empty scene to
  // committed BVH.
  template <class AddAll>
  double build_geometries(const AddAll& add_all) {
    release_scene();
    const auto start = std::chrono::steady_clock::now();
    scene_ = rtcNewScene(device_);
    add_all([this](RTCGeometryType type, const auto& fill) {
      RTCGeometry geometry = rtcNewGeometry(device_, type);
      fill(geometry);
      return attach(geometry);
    });
    commit_scene();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // hits[i] = rtcIntersect1's closest hit on rays[i], its t and the primitive
  // id(geomID, primID) gives, or none. Throws std::logic_error before the
  // first build.
  template <class Id>
  void intersect_with_ids(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                          unsigned threads, const Id& id) const {
    if (!scene_) throw std::logic_error("embree: intersect before build");
    for_each_ray(count, threads, [&](RTCIntersectContext& context, std::size_t i) {
      RTCRayHit query;
      query.ray = to_embree(rays[i]);
      query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene_, &context, &query);
      if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
        hits[i].reset();
      } else {
        hits[i] = Hit{query.ray.tfar, id(query.hit.geomID, query.hit.primID)};
      }
    });
  }

  // Throws std::runtime_error naming `what` if the device has recorded an error.
  void check(const char* what) const;

 private:
  void release_scene();
  // Commits the geometry and attaches it to the scene; returns its geomID.
  unsigned attach(RTCGeometry geometry);
  void commit_scene();

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace occlusion::bench
