#include "occlusion/core/triangle_octree.hpp"

#include "octree_impl.hpp"

namespace occlusion {

template class Octree<PackedTriangle>;

std::vector<PackedTriangle> pack_triangles(const std::vector<Triangle>& triangles) {
  std::vector<PackedTriangle> packed;
  packed.reserve(triangles.size());
  for (const Triangle& tri : triangles) packed.emplace_back(tri);
  return packed;
}

LargeVector<PackedTriangle> pack_triangles(const TriangleMesh& mesh,
                                           const Eigen::Vector3d& origin) {
  LargeVector<PackedTriangle> packed;
  packed.reserve(mesh.face_count());
  for (const auto& face : mesh.faces) {
    packed.emplace_back(Triangle{(mesh.vertices[face[0]] - origin).cast<float>(),
                                 (mesh.vertices[face[1]] - origin).cast<float>(),
                                 (mesh.vertices[face[2]] - origin).cast<float>()});
  }
  return packed;
}

}  // namespace occlusion
