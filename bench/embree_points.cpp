#include "embree_points.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace occlusion::bench {

namespace {

// As in embree_scene.cpp: small enough to balance rays of uneven cost, large
// enough that the shared counter is rarely contended.
constexpr std::size_t kChunk = 4096;

RTCRay to_embree(const Ray& in) {
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

// Calls body(i) for every i < count, in chunks handed out to `threads` std::threads.
template <class Body>
void for_each_ray(std::size_t count, unsigned threads, const Body& body) {
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t begin; (begin = next.fetch_add(kChunk)) < count;) {
      const std::size_t end = std::min(count, begin + kChunk);
      for (std::size_t i = begin; i < end; ++i) body(context, i);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(1u, threads); ++t) pool.emplace_back(work);
  for (std::thread& thread : pool) thread.join();
}

}  // namespace

EmbreePoints::EmbreePoints(unsigned threads) {
  const std::string config = "threads=" + std::to_string(std::max(1u, threads));
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("embree: rtcNewDevice failed");
  if (!rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_POINT_GEOMETRY_SUPPORTED)) {
    rtcReleaseDevice(device_);
    throw std::runtime_error("embree: this Embree was built without point geometry");
  }
}

EmbreePoints::~EmbreePoints() {
  if (scene_) rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void EmbreePoints::check(const char* what) const {
  const RTCError error = rtcGetDeviceError(device_);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("embree: ") + what + " failed with error " +
                             std::to_string(static_cast<int>(error)));
  }
}

double EmbreePoints::build(const std::vector<Sphere>& spheres) {
  if (scene_) {
    rtcReleaseScene(scene_);
    scene_ = nullptr;
  }
  const auto start = std::chrono::steady_clock::now();
  scene_ = rtcNewScene(device_);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), spheres.size()));
  check("rtcSetNewGeometryBuffer");
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    vertices[4 * i + 0] = spheres[i].center.x();
    vertices[4 * i + 1] = spheres[i].center.y();
    vertices[4 * i + 2] = spheres[i].center.z();
    vertices[4 * i + 3] = spheres[i].radius;
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
  check("rtcCommitScene");
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void EmbreePoints::intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                             unsigned threads) const {
  if (!scene_) throw std::logic_error("EmbreePoints::intersect before build");
  for_each_ray(count, threads, [&](RTCIntersectContext& context, std::size_t i) {
    RTCRayHit query;
    query.ray = to_embree(rays[i]);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
      hits[i].reset();
    } else {
      hits[i] = Hit{query.ray.tfar, query.hit.primID};
    }
  });
}

void EmbreePoints::occluded(const Ray* rays, std::size_t count, std::uint8_t* occluded,
                            unsigned threads) const {
  if (!scene_) throw std::logic_error("EmbreePoints::occluded before build");
  for_each_ray(count, threads, [&](RTCIntersectContext& context, std::size_t i) {
    RTCRay ray = to_embree(rays[i]);
    rtcOccluded1(scene_, &context, &ray);
    // Embree marks an occluded ray by setting tfar to -infinity.
    occluded[i] = ray.tfar < 0.0f ? 1 : 0;
  });
}

}  // namespace occlusion::bench
