#pragma once
// The reference the octree is checked against: every shape, in order, with
// the same kernel (shape_hit) and the same tie rule (equal t: lower id).

#include <optional>
#include <vector>

#include "occlusion/core/hit.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/sphere_octree.hpp"

namespace occlusion::testing {

// Shapes: a std::vector or a LargeVector of them.
template <class Shapes>
std::optional<Hit> brute_force_intersect(const Shapes& shapes, const Ray& query,
                                         PrimitiveId ignore_id = kNoPrimitive) {
  RayComponents<float> ray = ray_components(query);
  std::optional<Hit> best;
  for (PrimitiveId id = 0; id < shapes.size(); ++id) {
    if (id == ignore_id) continue;
    float t = 0.0f;
    if (shape_hit(ray, shapes[id], true, t) && (!best || t < best->t_hit)) {
      best = Hit{t, id};
      ray.t_max = t;
    }
  }
  return best;
}

}  // namespace occlusion::testing
