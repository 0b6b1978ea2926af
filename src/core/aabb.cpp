#include "occlusion/core/aabb.hpp"

#include <algorithm>
#include <cmath>

#include "occlusion/core/ray_lanes.hpp"

namespace occlusion {

Eigen::Vector3f safe_inverse(const Eigen::Vector3f& direction) {
  Eigen::Vector3f inv;
  for (int axis = 0; axis < 3; ++axis) {
    const float d = direction[axis];
    inv[axis] = lane_math::safe_inverse_component(d);
  }
  return inv;
}

Aabb pad_box(const Aabb& box) {
  if (box.empty()) return box;
  // 2^-18 relative is about 32 float ulps: well above the rounding of (lo - o).
  const float magnitude = std::max({box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff(),
                                    box.extent().maxCoeff(), 1e-30f});
  const float pad = magnitude * 0x1p-18f;
  Aabb padded = box;
  padded.lo.array() -= pad;
  padded.hi.array() += pad;
  return padded;
}

bool intersect_aabb(const Ray& ray, const Eigen::Vector3f& inv_direction, const Aabb& box,
                    float& t_enter, float& t_exit) {
  float t_near = ray.t_min;
  float t_far = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    if (ray.direction[axis] == 0.0f) {
      // Parallel to this slab: inside it (faces included) for every t, or never.
      if (ray.origin[axis] < box.lo[axis] || ray.origin[axis] > box.hi[axis]) return false;
      continue;
    }
    const float t0 = (box.lo[axis] - ray.origin[axis]) * inv_direction[axis];
    const float t1 = (box.hi[axis] - ray.origin[axis]) * inv_direction[axis];
    t_near = std::max(t_near, std::min(t0, t1));
    t_far = std::min(t_far, std::max(t0, t1));
  }
  if (t_near > t_far) return false;
  t_enter = t_near;
  t_exit = t_far;
  return true;
}

}  // namespace occlusion
