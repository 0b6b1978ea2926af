#pragma once
// Triangles and the Möller–Trumbore ray-triangle test.
//
// Rules, shared by every query in this library:
// - Interval: a hit counts iff t_min <= t <= t_max (closed).
// - Edges and vertices belong to the triangle: barycentric u >= 0, v >= 0,
//   u + v <= 1 are all closed, so a ray through an edge or a vertex hits.
//   Two triangles that share an edge are not made watertight beyond what
//   float rounding allows; the closed test makes exact cases (axis-aligned,
//   representable coordinates) hit at least one of them.
// - Parallel rays: if the direction lies in the triangle's plane, within a
//   relative tolerance |d . n| <= 1e-7 |d| |n|, the ray misses, even when it
//   slides along the triangle. Surfaces seen exactly edge-on hide nothing.
// - Degenerate triangles (zero area) are never hit.
// - Both faces are hit: no back-face culling (meshes are surfaces, not solids).

#include <Eigen/Geometry>
#include <optional>

#include "occlusion/core/aabb.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion {

struct Triangle {
  Eigen::Vector3f v0, v1, v2;

  Aabb bounds() const;
  Eigen::Vector3f centroid() const { return (v0 + v1 + v2) / 3.0f; }
  // Area in double precision: used for area weighting, where float
  // cancellation on thin triangles would bias the total.
  double area() const;
};

// The triangle in the form the intersection kernel wants: one vertex, two edges
// and the (unnormalised) normal e1 x e2 with its length precomputed.
struct PackedTriangle {
  Eigen::Vector3f v0, e1, e2, normal;
  float normal_length = 0.0f;

  PackedTriangle() = default;
  explicit PackedTriangle(const Triangle& tri);
  Aabb bounds() const;
  Eigen::Vector3f centroid() const { return v0 + (e1 + e2) / 3.0f; }
};

// Möller–Trumbore. Returns the hit parameter t, or nothing, under the rules above.
// `direction_length` is ray.direction.norm(), passed in so that a traversal
// computes it once per ray, not once per triangle.
std::optional<float> intersect_triangle(const Ray& ray, float direction_length,
                                        const PackedTriangle& tri);

inline std::optional<float> intersect_triangle(const Ray& ray, const Triangle& tri) {
  return intersect_triangle(ray, ray.direction.norm(), PackedTriangle(tri));
}

}  // namespace occlusion
