#pragma once
// The reference the octree is checked against: every triangle, in order, with
// the same kernel and the same tie rule (equal t: lower id).

#include <optional>
#include <vector>

#include "occlusion/core/hit.hpp"
#include "occlusion/core/triangle.hpp"

namespace occlusion::testing {

inline std::optional<Hit> brute_force_intersect(const std::vector<PackedTriangle>& triangles,
                                                const Ray& query,
                                                PrimitiveId ignore_id = kNoPrimitive) {
  Ray ray = query;
  const float length = ray.direction.norm();
  std::optional<Hit> best;
  for (PrimitiveId id = 0; id < triangles.size(); ++id) {
    if (id == ignore_id) continue;
    const auto t = intersect_triangle(ray, length, triangles[id]);
    if (t && (!best || *t < best->t_hit)) {
      best = Hit{*t, id};
      ray.t_max = *t;
    }
  }
  return best;
}

}  // namespace occlusion::testing
