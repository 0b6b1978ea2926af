#include "embree_points.hpp"

#include <stdexcept>

namespace occlusion::bench {

EmbreePoints::EmbreePoints(unsigned threads) : EmbreeTracer(threads) {
  if (!rtcGetDeviceProperty(device(), RTC_DEVICE_PROPERTY_POINT_GEOMETRY_SUPPORTED)) {
    throw std::runtime_error("embree: this Embree was built without point geometry");
  }
}

double EmbreePoints::build(const LargeVector<Sphere>& spheres) {
  return build_scene(RTC_GEOMETRY_TYPE_SPHERE_POINT, [&](RTCGeometry geometry) {
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), spheres.size()));
    check("rtcSetNewGeometryBuffer");
    for (std::size_t i = 0; i < spheres.size(); ++i) {
      vertices[4 * i + 0] = spheres[i].center.x();
      vertices[4 * i + 1] = spheres[i].center.y();
      vertices[4 * i + 2] = spheres[i].center.z();
      vertices[4 * i + 3] = spheres[i].radius;
    }
  });
}

void EmbreePoints::intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                             unsigned threads) const {
  const RTCScene built = scene();
  if (!built) throw std::logic_error("EmbreePoints::intersect before build");
  for_each_ray(count, threads, [&](RTCIntersectContext& context, std::size_t i) {
    RTCRayHit query;
    query.ray = to_embree(rays[i]);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(built, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
      hits[i].reset();
    } else {
      hits[i] = Hit{query.ray.tfar, query.hit.primID};
    }
  });
}

}  // namespace occlusion::bench
