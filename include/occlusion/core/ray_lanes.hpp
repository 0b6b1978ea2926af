#pragma once
// A ray in components, generic over the number type, so that each primitive
// test is written once and runs on one ray (Num = float) or on a packet of rays
// at once (Num = a SIMD lane type of the octree's packet traversal). Both
// instantiations perform the same IEEE operations in the same order, which is
// what makes packets return exactly what single rays return.
//
// A Num provides + - * / and unary -, comparisons returning a mask (bool for
// float; a lane bit mask for lanes, false for NaN), and the free functions
// below. Masks combine with & and test with `!mask` (no lane left).

#include <cmath>
#include <type_traits>

#include "occlusion/core/aabb.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion {

template <class Num>
struct RayComponents {
  Num origin_x, origin_y, origin_z;
  Num direction_x, direction_y, direction_z;
  Num t_min, t_max;
  // |direction| and |direction|^2, computed once per ray.
  Num length, length_squared;
};

namespace lane_math {

inline float abs(float x) {
  return std::fabs(x);
}
inline float sqrt(float x) {
  return std::sqrt(x);
}
// +1 or -1 with the sign bit of x.
inline float sign_of(float x) {
  return std::copysign(1.0f, x);
}
inline float select(bool mask, float if_set, float if_clear) {
  return mask ? if_set : if_clear;
}

// x*x + y*y + z*z in this order: the lane types must use the same one.
template <class Num>
inline Num dot3(const Num& ax, const Num& ay, const Num& az, const Num& bx, const Num& by,
                const Num& bz) {
  return ax * bx + ay * by + az * bz;
}

// safe_inverse (aabb.hpp) of one component: 1 / d, or kHugeInverse with the
// sign of d where d is +0 or -0. Written once for single rays and packets.
template <class Num>
inline Num safe_inverse_component(const Num& d) {
  const auto zero = (d <= Num(0.0f)) & (Num(0.0f) <= d);
  return select(zero, sign_of(d) * Num(kHugeInverse), Num(1.0f) / d);
}

// Whether the triangle test stops once no ray is left. A single ray stops. A
// packet carries on with its mask: whether every lane has failed is data, and
// on bench_moc the mispredicted branches cost more than finishing the test
// (shadow rays 1.04 -> 1.17x Embree). Masked lanes change no answer. The
// sphere test keeps its branch: a square root and a division more per miss
// cost bench_poc's closest hits about 10%.
template <class Num, class Mask>
inline bool stop_early(Mask active) {
  return std::is_same_v<Num, float> && !active;
}

}  // namespace lane_math

inline RayComponents<float> ray_components(const Ray& ray) {
  RayComponents<float> r;
  r.origin_x = ray.origin.x();
  r.origin_y = ray.origin.y();
  r.origin_z = ray.origin.z();
  r.direction_x = ray.direction.x();
  r.direction_y = ray.direction.y();
  r.direction_z = ray.direction.z();
  r.t_min = ray.t_min;
  r.t_max = ray.t_max;
  r.length_squared = lane_math::dot3(r.direction_x, r.direction_y, r.direction_z, r.direction_x,
                                     r.direction_y, r.direction_z);
  r.length = std::sqrt(r.length_squared);
  return r;
}

}  // namespace occlusion
