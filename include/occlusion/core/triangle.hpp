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
#include "occlusion/core/ray_lanes.hpp"

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

// Möller–Trumbore under the rules above, for one ray (Num = float) or a packet
// (ray_lanes.hpp). `active` says which rays to test; returns those that hit,
// with their hit parameter in `t_hit` (unspecified for the others). Inline: it
// is the octree's leaf test.
template <class Num, class Mask>
inline Mask triangle_hit(const RayComponents<Num>& ray, const PackedTriangle& tri, Mask active,
                         Num& t_hit) {
  // Unqualified below: a lane type brings its own through argument lookup.
  using lane_math::abs, lane_math::dot3, lane_math::select, lane_math::sign_of, lane_math::sqrt;
  // det = e1 . (d x e2) = -(d . n), using the stored normal.
  const Num det = -dot3(ray.direction_x, ray.direction_y, ray.direction_z, Num(tri.normal.x()),
                        Num(tri.normal.y()), Num(tri.normal.z()));
  // Parallel to the plane, or a degenerate triangle (n = 0): no hit.
  active = active & (abs(det) > kParallelTolerance * ray.length * tri.normal_length);
  if (!active) return active;
  // Barycentric tests on values scaled by |det|, so that the division is paid
  // only by rays that do cross the triangle's interior or boundary.
  const Num sign = sign_of(det);
  const Num abs_det = det * sign;
  const Num s_x = ray.origin_x - tri.v0.x();
  const Num s_y = ray.origin_y - tri.v0.y();
  const Num s_z = ray.origin_z - tri.v0.z();
  // p = d x e2
  const Num p_x = ray.direction_y * tri.e2.z() - ray.direction_z * tri.e2.y();
  const Num p_y = ray.direction_z * tri.e2.x() - ray.direction_x * tri.e2.z();
  const Num p_z = ray.direction_x * tri.e2.y() - ray.direction_y * tri.e2.x();
  const Num u_scaled = dot3(s_x, s_y, s_z, p_x, p_y, p_z) * sign;
  active = active & (u_scaled >= 0.0f) & (u_scaled <= abs_det);
  if (lane_math::stop_early<Num>(active)) return active;
  // q = s x e1
  const Num q_x = s_y * tri.e1.z() - s_z * tri.e1.y();
  const Num q_y = s_z * tri.e1.x() - s_x * tri.e1.z();
  const Num q_z = s_x * tri.e1.y() - s_y * tri.e1.x();
  const Num v_scaled =
      dot3(ray.direction_x, ray.direction_y, ray.direction_z, q_x, q_y, q_z) * sign;
  active = active & (v_scaled >= 0.0f) & (u_scaled + v_scaled <= abs_det);
  if (lane_math::stop_early<Num>(active)) return active;
  t_hit = dot3(Num(tri.e2.x()), Num(tri.e2.y()), Num(tri.e2.z()), q_x, q_y, q_z) / det;
  return active & (t_hit >= ray.t_min) & (t_hit <= ray.t_max);
}

// One ray: the hit parameter t, or nothing.
inline std::optional<float> intersect_triangle(const RayComponents<float>& ray,
                                               const PackedTriangle& tri) {
  float t = 0.0f;
  if (triangle_hit(ray, tri, true, t)) return t;
  return std::nullopt;
}

inline std::optional<float> intersect_triangle(const Ray& ray, const Triangle& tri) {
  return intersect_triangle(ray_components(ray), PackedTriangle(tri));
}

}  // namespace occlusion
