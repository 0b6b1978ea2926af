#pragma once
// One ray through the flattened octree, from any inner node down: the
// reference traversal (Octree::intersect / occluded start it at the root), and
// what a packet hands a lane to when too few of its lanes go on together to
// pay for testing them as a packet.

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "occlusion/core/hit.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/ray_lanes.hpp"
#include "octree_slab.hpp"

namespace occlusion::octree_detail {

template <class Shape>
struct TreeView {
  const OctreeNode* nodes = nullptr;  // null for an empty tree
  const Shape* shapes = nullptr;
  const PrimitiveId* ids = nullptr;
  float magnitude = 0.0f;  // the largest coordinate magnitude of the scene's boxes
};

// Traces `ray` through the subtree under inner node `node_index`, starting
// from `best` (closest hit: the best so far, whose t is ray.t_max), and
// returns the best hit (any hit: the first found). `inverse` is
// safe_inverse(direction).
template <class Shape, bool kAnyHit>
inline std::optional<Hit> trace_single_ray(const TreeView<Shape>& tree, RayComponents<float> ray,
                                           const Eigen::Vector3f& inverse, PrimitiveId ignore_id,
                                           std::uint32_t node_index, std::optional<Hit> best) {
  const Eigen::Vector3f origin(ray.origin_x, ray.origin_y, ray.origin_z);
  SlabRay slab(origin, inverse, ray.t_min, ray.t_max);
  const int near_octant = near_octant_of(ray.direction_x, ray.direction_y, ray.direction_z);

  struct Entry {
    OctreeChild child;
    float t_enter;
  };
  Entry stack[kStackSize];
  std::size_t top = 0;
  stack[top++] = {OctreeChild{node_index, 0}, ray.t_min};

  while (top > 0) {
    const Entry entry = stack[--top];
    // Only a closest-hit query shrinks t_max below what a child was pushed with.
    if (!kAnyHit && entry.t_enter > ray.t_max) continue;
    if (entry.child.count > 0) {
      const std::uint32_t end = entry.child.index + entry.child.count;
      for (std::uint32_t i = entry.child.index; i < end; ++i) {
        const PrimitiveId id = tree.ids[i];
        if (id == ignore_id) continue;
        float t = 0.0f;
        if (!shape_hit(ray, tree.shapes[i], true, t)) continue;
        if constexpr (kAnyHit) {
          return Hit{t, id};
        } else {
          // t <= t_max == best->t_hit here, so this takes a closer hit, and on a tie
          // the lower id: the answer does not depend on traversal order.
          if (!best || t < best->t_hit || id < best->primitive_id) {
            best = Hit{t, id};
            ray.t_max = t;
            slab.set_t_max(t);
          }
        }
      }
      continue;
    }

    const OctreeNode& node = tree.nodes[entry.child.index];
    // All eight slots in one fixed-length loop the compiler can vectorise;
    // empty slots are masked out below.
    float t_near[8];
    std::uint32_t hit_mask = slab_test_8(node, slab, t_near);
    hit_mask &= occupied_slots(node);
    // Push farthest first so that the nearest is popped next: relabel slot k as
    // k ^ near_octant (front-to-back rank) and push from the highest rank down.
    std::uint32_t ranked = kRankedMask[near_octant][hit_mask];
    while (ranked != 0) {
      const int rank = 31 - __builtin_clz(ranked);
      ranked &= ~(1u << rank);
      const int k = rank ^ near_octant;
      stack[top++] = Entry{node.child[k], t_near[k]};
    }
  }
  return best;
}

}  // namespace occlusion::octree_detail
