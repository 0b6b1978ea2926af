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

}  // namespace occlusion
