#include "embree_scene.hpp"

#include <algorithm>
#include <cstdint>

namespace occlusion::bench {

double EmbreeScene::build(const TriangleMesh& mesh) {
  return build_scene(RTC_GEOMETRY_TYPE_TRIANGLE, [&](RTCGeometry geometry) {
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), mesh.vertices.size()));
    auto* indices = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), mesh.faces.size()));
    check("rtcSetNewGeometryBuffer");
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(mesh.vertices[i][k]);
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      std::copy(mesh.faces[f].begin(), mesh.faces[f].end(), indices + 3 * f);
    }
  });
}

void EmbreeScene::intersect(const Ray* rays, std::size_t count, std::optional<Hit>* hits,
                            unsigned threads) const {
  intersect_with_ids(rays, count, hits, threads,
                     [](unsigned, unsigned primitive) { return PrimitiveId{primitive}; });
}

}  // namespace occlusion::bench
