#pragma once
// Axis-aligned bounding box and the ray-box slab test.

#include <Eigen/Core>
#include <limits>

#include "occlusion/core/ray.hpp"

namespace occlusion {

struct Aabb {
  // An empty box (lo > hi) so that extend() of the first point yields that point.
  Eigen::Vector3f lo{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                     std::numeric_limits<float>::infinity()};
  Eigen::Vector3f hi{-std::numeric_limits<float>::infinity(),
                     -std::numeric_limits<float>::infinity(),
                     -std::numeric_limits<float>::infinity()};

  bool empty() const { return (lo.array() > hi.array()).any(); }
  void extend(const Eigen::Vector3f& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void extend(const Aabb& other) {
    lo = lo.cwiseMin(other.lo);
    hi = hi.cwiseMax(other.hi);
  }
  Eigen::Vector3f center() const { return 0.5f * (lo + hi); }
  Eigen::Vector3f extent() const { return hi - lo; }
  bool contains(const Eigen::Vector3f& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
};

// What safe_inverse puts for a zero component. Large but finite: (lo - o) *
// kHugeInverse stays finite for any scene coordinate, and 0 * kHugeInverse is
// 0 rather than NaN.
inline constexpr float kHugeInverse = 1e30f;

// Reciprocal direction for slab tests. A zero component is replaced by a huge
// finite value of the same sign (+ for +0, - for -0) so that a branch-free slab
// test never computes 0 * inf = NaN. Such a test is only right for a ray lying
// exactly in a face plane if the box is padded (see pad_box); intersect_aabb
// below handles that case exactly instead.
Eigen::Vector3f safe_inverse(const Eigen::Vector3f& direction);

// Slab test against the closed box and the closed interval [t_min, t_max].
// On a hit, returns true and writes the parameter interval inside the box,
// clipped to [t_min, t_max]. A ray that only touches a face, edge or corner
// hits (the box is closed). A ray parallel to a slab and outside it misses.
// The box grown by a few float ulps of its coordinates on every side, so that a
// branch-free slab test also catches rays that lie in one of its face planes.
// For culling only: a padded box may admit a ray the exact box would not.
Aabb pad_box(const Aabb& box);

bool intersect_aabb(const Ray& ray, const Eigen::Vector3f& inv_direction, const Aabb& box,
                    float& t_enter, float& t_exit);

}  // namespace occlusion
