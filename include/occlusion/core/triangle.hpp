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
#include <cmath>
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

// Relative tolerance of the parallel test |d . n| <= kParallelTolerance |d| |n|:
// about the float rounding of the determinant itself.
inline constexpr float kParallelTolerance = 1e-7f;

// Möller–Trumbore. Returns the hit parameter t, or nothing, under the rules above.
// `direction_length` is ray.direction.norm(), passed in so that a traversal
// computes it once per ray, not once per triangle. Inline: it is the octree's
// leaf test.
inline std::optional<float> intersect_triangle(const Ray& ray, float direction_length,
                                               const PackedTriangle& tri) {
  // det = e1 . (d x e2) = -(d . n), using the stored normal.
  const float det = -ray.direction.dot(tri.normal);
  if (!(std::abs(det) > kParallelTolerance * direction_length * tri.normal_length)) {
    return std::nullopt;  // parallel to the plane, or a degenerate triangle (n = 0)
  }
  // Barycentric tests on values scaled by |det|, so that the division is paid
  // only by rays that do cross the triangle's interior or boundary.
  const float sign = det > 0.0f ? 1.0f : -1.0f;
  const float abs_det = det * sign;
  const Eigen::Vector3f s = ray.origin - tri.v0;
  const Eigen::Vector3f p = ray.direction.cross(tri.e2);
  const float u_scaled = s.dot(p) * sign;
  if (u_scaled < 0.0f || u_scaled > abs_det) return std::nullopt;
  const Eigen::Vector3f q = s.cross(tri.e1);
  const float v_scaled = ray.direction.dot(q) * sign;
  if (v_scaled < 0.0f || u_scaled + v_scaled > abs_det) return std::nullopt;
  const float t = tri.e2.dot(q) / det;
  if (t < ray.t_min || t > ray.t_max) return std::nullopt;
  return t;
}

inline std::optional<float> intersect_triangle(const Ray& ray, const Triangle& tri) {
  return intersect_triangle(ray, ray.direction.norm(), PackedTriangle(tri));
}

}  // namespace occlusion
