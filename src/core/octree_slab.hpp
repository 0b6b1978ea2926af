#pragma once
// The ray against the eight child boxes of an octree node, all at once. This is
// the traversal's innermost step, so it is written with SSE2 (baseline on
// x86-64) where available, and as a plain loop elsewhere. Both compute
// t = lo * inv - origin * inv, which is within rounding of (lo - origin) * inv;
// the node boxes are padded by far more than that rounding (pad_box).

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>

#include "occlusion/core/octree.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace occlusion::octree_detail {

// Deep enough for any scene: the cell edge halves at each level, so 32 levels
// reach 1e-10 of the scene size, below float resolution.
inline constexpr int kMaxDepthLimit = 32;
inline constexpr std::size_t kStackSize = 8 * (kMaxDepthLimit + 2);

// The octant a ray travelling along (x, y, z) enters first: the lower half
// along each axis it travels up. Visiting slots in the order k ^ near_octant
// is front to back.
inline int near_octant_of(float x, float y, float z) {
  return (x < 0.0f ? 1 : 0) | (y < 0.0f ? 2 : 0) | (z < 0.0f ? 4 : 0);
}

// kRankedMask[s][m]: the bit mask m with bit k moved to bit k ^ s.
struct RankedMaskTable {
  std::uint8_t table[8][256];
  constexpr RankedMaskTable() : table{} {
    for (int s = 0; s < 8; ++s) {
      for (int m = 0; m < 256; ++m) {
        int ranked = 0;
        for (int k = 0; k < 8; ++k) {
          if (m & (1 << k)) ranked |= 1 << (k ^ s);
        }
        table[s][m] = static_cast<std::uint8_t>(ranked);
      }
    }
  }
  constexpr const std::uint8_t* operator[](int s) const { return table[s]; }
};
inline constexpr RankedMaskTable kRankedMask{};

#if defined(__SSE2__)

// Bit k set: slot k of `node` holds a child.
inline std::uint32_t occupied_slots(const OctreeNode& node) {
  // The counts are the odd words of `child`: gather four at a time.
  const auto* words = reinterpret_cast<const __m128*>(node.child);
  const __m128i counts_low = _mm_castps_si128(_mm_shuffle_ps(
      _mm_load_ps(reinterpret_cast<const float*>(words)),
      _mm_load_ps(reinterpret_cast<const float*>(words + 1)), _MM_SHUFFLE(3, 1, 3, 1)));
  const __m128i counts_high = _mm_castps_si128(_mm_shuffle_ps(
      _mm_load_ps(reinterpret_cast<const float*>(words + 2)),
      _mm_load_ps(reinterpret_cast<const float*>(words + 3)), _MM_SHUFFLE(3, 1, 3, 1)));
  const __m128i empty = _mm_set1_epi32(static_cast<int>(OctreeChild::kEmptySlot));
  const int empty_slots =
      _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(counts_low, empty))) |
      (_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(counts_high, empty))) << 4);
  return ~static_cast<std::uint32_t>(empty_slots) & 0xffu;
}

struct SlabRay {
  __m128 inv_x, inv_y, inv_z;
  __m128 org_inv_x, org_inv_y, org_inv_z;  // origin * inv
  __m128 t_min, t_max;

  SlabRay(const Eigen::Vector3f& origin, const Eigen::Vector3f& inv, float t_lo, float t_hi)
      : inv_x(_mm_set1_ps(inv.x())),
        inv_y(_mm_set1_ps(inv.y())),
        inv_z(_mm_set1_ps(inv.z())),
        org_inv_x(_mm_set1_ps(origin.x() * inv.x())),
        org_inv_y(_mm_set1_ps(origin.y() * inv.y())),
        org_inv_z(_mm_set1_ps(origin.z() * inv.z())),
        t_min(_mm_set1_ps(t_lo)),
        t_max(_mm_set1_ps(t_hi)) {}
  void set_t_max(float t_hi) { t_max = _mm_set1_ps(t_hi); }
};

// Four slots starting at `first`: writes their entry t, returns their hit bits.
inline int slab_test_4(const OctreeNode& node, int first, const SlabRay& ray, float* t_near) {
  const __m128 x0 =
      _mm_sub_ps(_mm_mul_ps(_mm_load_ps(node.lo_x + first), ray.inv_x), ray.org_inv_x);
  const __m128 x1 =
      _mm_sub_ps(_mm_mul_ps(_mm_load_ps(node.hi_x + first), ray.inv_x), ray.org_inv_x);
  const __m128 y0 =
      _mm_sub_ps(_mm_mul_ps(_mm_load_ps(node.lo_y + first), ray.inv_y), ray.org_inv_y);
  const __m128 y1 =
      _mm_sub_ps(_mm_mul_ps(_mm_load_ps(node.hi_y + first), ray.inv_y), ray.org_inv_y);
  const __m128 z0 =
      _mm_sub_ps(_mm_mul_ps(_mm_load_ps(node.lo_z + first), ray.inv_z), ray.org_inv_z);
  const __m128 z1 =
      _mm_sub_ps(_mm_mul_ps(_mm_load_ps(node.hi_z + first), ray.inv_z), ray.org_inv_z);
  const __m128 enter = _mm_max_ps(_mm_max_ps(_mm_min_ps(x0, x1), _mm_min_ps(y0, y1)),
                                  _mm_max_ps(_mm_min_ps(z0, z1), ray.t_min));
  const __m128 exit = _mm_min_ps(_mm_min_ps(_mm_max_ps(x0, x1), _mm_max_ps(y0, y1)),
                                 _mm_min_ps(_mm_max_ps(z0, z1), ray.t_max));
  _mm_storeu_ps(t_near + first, enter);
  return _mm_movemask_ps(_mm_cmple_ps(enter, exit));
}

inline std::uint32_t slab_test_8(const OctreeNode& node, const SlabRay& ray, float* t_near) {
  return static_cast<std::uint32_t>(slab_test_4(node, 0, ray, t_near) |
                                    (slab_test_4(node, 4, ray, t_near) << 4));
}

#else

inline std::uint32_t occupied_slots(const OctreeNode& node) {
  std::uint32_t mask = 0;
  for (int k = 0; k < 8; ++k) {
    mask |= static_cast<std::uint32_t>(node.child[k].count != OctreeChild::kEmptySlot) << k;
  }
  return mask;
}

struct SlabRay {
  Eigen::Vector3f inv, org_inv;
  float t_min, t_max;

  SlabRay(const Eigen::Vector3f& origin, const Eigen::Vector3f& inv_direction, float t_lo,
          float t_hi)
      : inv(inv_direction), org_inv(origin.cwiseProduct(inv_direction)), t_min(t_lo), t_max(t_hi) {}
  void set_t_max(float t_hi) { t_max = t_hi; }
};

inline std::uint32_t slab_test_8(const OctreeNode& node, const SlabRay& ray, float* t_near) {
  std::uint32_t mask = 0;
  for (int k = 0; k < 8; ++k) {
    const float x0 = node.lo_x[k] * ray.inv.x() - ray.org_inv.x();
    const float x1 = node.hi_x[k] * ray.inv.x() - ray.org_inv.x();
    const float y0 = node.lo_y[k] * ray.inv.y() - ray.org_inv.y();
    const float y1 = node.hi_y[k] * ray.inv.y() - ray.org_inv.y();
    const float z0 = node.lo_z[k] * ray.inv.z() - ray.org_inv.z();
    const float z1 = node.hi_z[k] * ray.inv.z() - ray.org_inv.z();
    const float enter = std::max(std::max(std::min(x0, x1), std::min(y0, y1)),
                                 std::max(std::min(z0, z1), ray.t_min));
    const float exit = std::min(std::min(std::max(x0, x1), std::max(y0, y1)),
                                std::min(std::max(z0, z1), ray.t_max));
    t_near[k] = enter;
    mask |= static_cast<std::uint32_t>(enter <= exit) << k;
  }
  return mask;
}

#endif

}  // namespace occlusion::octree_detail
