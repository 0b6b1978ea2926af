#include "embree_points.hpp"

#include <stdexcept>

namespace occlusion::bench {

namespace {

// Fills a new FLOAT4 vertex buffer (x, y, z, radius) with center(i) and
// radius(i) for i < count.
template <class Center, class Radius>
void set_points(RTCGeometry geometry, std::size_t count, const Center& center,
                const Radius& radius) {
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), count));
  if (!vertices) throw std::runtime_error("embree: rtcSetNewGeometryBuffer (vertex) failed");
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3f& c = center(i);
    vertices[4 * i + 0] = c.x();
    vertices[4 * i + 1] = c.y();
    vertices[4 * i + 2] = c.z();
    vertices[4 * i + 3] = radius(i);
  }
}

void require_point_geometry(RTCDevice device) {
  if (!rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_POINT_GEOMETRY_SUPPORTED)) {
    throw std::runtime_error("embree: this Embree was built without point geometry");
  }
}

}  // namespace

EmbreePoints::EmbreePoints(unsigned threads) : EmbreeTracer(threads) {
  require_point_geometry(device());
}

double EmbreePoints::build(const LargeVector<Sphere>& spheres) {
  return build_scene(RTC_GEOMETRY_TYPE_SPHERE_POINT, [&](RTCGeometry geometry) {
    set_points(
        geometry, spheres.size(),
        [&](std::size_t i) -> const Eigen::Vector3f& { return spheres[i].center; },
        [&](std::size_t i) { return spheres[i].radius; });
  });
}

void EmbreePoints::intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                             unsigned threads) const {
  intersect_with_ids(rays, count, hits, threads,
                     [](unsigned, unsigned primitive) { return PrimitiveId{primitive}; });
}

EmbreeDiscs::EmbreeDiscs(unsigned threads) : EmbreeTracer(threads) {
  require_point_geometry(device());
}

double EmbreeDiscs::build(const LargeVector<Surfel>& surfels) {
  const auto start = std::chrono::steady_clock::now();
  disc_ids_.clear();
  sphere_ids_.clear();
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    (surfels[i].oriented() ? disc_ids_ : sphere_ids_).push_back(static_cast<PrimitiveId>(i));
  }
  const double split =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return split + build_geometries([&](const auto& add) {
           const auto points = [&](RTCGeometry geometry, const std::vector<PrimitiveId>& ids) {
             set_points(
                 geometry, ids.size(),
                 [&](std::size_t i) -> const Eigen::Vector3f& { return surfels[ids[i]].center; },
                 [&](std::size_t i) { return surfels[ids[i]].radius; });
           };
           disc_geometry_ = RTC_INVALID_GEOMETRY_ID;
           if (!disc_ids_.empty()) {
             disc_geometry_ = add(RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT, [&](RTCGeometry geometry) {
               points(geometry, disc_ids_);
               auto* normals = static_cast<float*>(
                   rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3,
                                           3 * sizeof(float), disc_ids_.size()));
               if (!normals)
                 throw std::runtime_error("embree: rtcSetNewGeometryBuffer (normal) failed");
               for (std::size_t i = 0; i < disc_ids_.size(); ++i) {
                 const Eigen::Vector3f& n = surfels[disc_ids_[i]].normal;
                 normals[3 * i + 0] = n.x();
                 normals[3 * i + 1] = n.y();
                 normals[3 * i + 2] = n.z();
               }
             });
           }
           if (!sphere_ids_.empty()) {
             add(RTC_GEOMETRY_TYPE_SPHERE_POINT,
                 [&](RTCGeometry geometry) { points(geometry, sphere_ids_); });
           }
         });
}

void EmbreeDiscs::intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                            unsigned threads) const {
  intersect_with_ids(rays, count, hits, threads, [this](unsigned geometry, unsigned primitive) {
    return geometry == disc_geometry_ ? disc_ids_[primitive] : sphere_ids_[primitive];
  });
}

}  // namespace occlusion::bench
