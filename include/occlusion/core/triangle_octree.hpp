#pragma once
// The octree over triangles: meshes as seen by shadow rays. A hit's primitive
// id is the triangle's index in the construction vector.

#include <optional>
#include <vector>

#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/triangle.hpp"

namespace occlusion {

// The kernel the triangle octree calls.
template <class Num, class Mask>
inline Mask shape_hit(const RayComponents<Num>& ray, const PackedTriangle& tri, Mask active,
                      Num& t_hit) {
  return triangle_hit(ray, tri, active, t_hit);
}

using TriangleOctree = Octree<PackedTriangle>;
extern template class Octree<PackedTriangle>;

// Convenience: pack triangles for the octree.
std::vector<PackedTriangle> pack_triangles(const std::vector<Triangle>& triangles);

// The mesh's faces relative to `origin`, in float, packed: straight from the
// mesh into the buffer the octree is built from, with no copy between.
LargeVector<PackedTriangle> pack_triangles(const TriangleMesh& mesh, const Eigen::Vector3d& origin);

}  // namespace occlusion
