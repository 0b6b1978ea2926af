#pragma once
// A packet's rays as one interval ray, to cull a node's children for the
// whole packet with one test of all eight boxes before testing them lane by
// lane. Over the packet, each axis has an interval of origins [o_lo, o_hi] and
// of inverse directions [i_lo, i_hi] of one sign; a box's entry parameter on an
// axis is (near - o) * i, whose smallest value over the packet lies at a corner
// of those intervals, and likewise the largest exit. If the largest of the
// smallest entries exceeds the smallest of the largest exits, no lane can hit
// the box. Both bounds are widened by more than the rounding of either the
// interval's or a lane's own arithmetic, so a box a lane's test would pass is
// never culled: culling changes only the work done, never an answer.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "occlusion/core/octree.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace occlusion::octree_detail {

struct PacketInterval {
  // Per axis: the planes a ray enters and leaves a box through (lo or hi,
  // chosen by the sign of the direction), and the origin bound giving the
  // extreme value against each.
  const float (OctreeNode::*near_plane[3])[8];
  const float (OctreeNode::*far_plane[3])[8];
  float origin_near[3], origin_far[3];
  float inverse_lo[3], inverse_hi[3];
  float margin[3];
  float t_lo, t_hi;  // the packet's smallest t_min, largest t_max
};

// Beyond this, products of inverse directions and coordinates lose the
// margin's meaning (a ray along an axis has inverse 1e30): no culling then.
inline constexpr float kIntervalLimit = 1e18f;

// A node's lower and upper box planes, by axis.
inline constexpr const float (OctreeNode::*kLowerPlane[3])[8] = {
    &OctreeNode::lo_x, &OctreeNode::lo_y, &OctreeNode::lo_z};
inline constexpr const float (OctreeNode::*kUpperPlane[3])[8] = {
    &OctreeNode::hi_x, &OctreeNode::hi_y, &OctreeNode::hi_z};

// Builds the interval over the lanes in `live`; false if it cannot cull
// (directions of mixed signs, non-finite or extreme values).
// origin[axis][j] and inverse[axis][j] are lane j's.
inline bool make_packet_interval(const float* const origin[3], const float* const inverse[3],
                                 const float* t_min, const float* t_max, unsigned live,
                                 float scene_magnitude, PacketInterval& out) {
  if (live == 0) return false;
  float o_lo[3], o_hi[3], i_lo[3], i_hi[3];
  float t_lo = INFINITY, t_hi = -INFINITY;
  for (int axis = 0; axis < 3; ++axis) {
    o_lo[axis] = i_lo[axis] = INFINITY;
    o_hi[axis] = i_hi[axis] = -INFINITY;
  }
  for (unsigned rest = live; rest != 0; rest &= rest - 1) {
    const unsigned j = static_cast<unsigned>(__builtin_ctz(rest));
    for (int axis = 0; axis < 3; ++axis) {
      o_lo[axis] = std::min(o_lo[axis], origin[axis][j]);
      o_hi[axis] = std::max(o_hi[axis], origin[axis][j]);
      i_lo[axis] = std::min(i_lo[axis], inverse[axis][j]);
      i_hi[axis] = std::max(i_hi[axis], inverse[axis][j]);
    }
    t_lo = std::min(t_lo, t_min[j]);
    t_hi = std::max(t_hi, t_max[j]);
  }
  for (int axis = 0; axis < 3; ++axis) {
    const bool up = i_lo[axis] > 0.0f;
    if (!(up || i_hi[axis] < 0.0f)) return false;  // mixed signs, or NaN
    const float i_mag = std::max(std::fabs(i_lo[axis]), std::fabs(i_hi[axis]));
    const float o_mag = std::max(std::fabs(o_lo[axis]), std::fabs(o_hi[axis]));
    if (!(i_mag < kIntervalLimit && o_mag < kIntervalLimit)) return false;
    // 2^-20 relative: eight times the rounding of (near - o) * i plus that of
    // a lane's near * i - o * i, both at most a few ulps of (|near| + |o|) |i|.
    out.margin[axis] = 0x1p-20f * (scene_magnitude + o_mag) * i_mag;
    if (!std::isfinite(out.margin[axis])) return false;
    out.near_plane[axis] = up ? kLowerPlane[axis] : kUpperPlane[axis];
    out.far_plane[axis] = up ? kUpperPlane[axis] : kLowerPlane[axis];
    // Entry (near - o) * i is smallest at the largest o going up, the
    // smallest o going down; the exit is largest at the opposite end.
    out.origin_near[axis] = up ? o_hi[axis] : o_lo[axis];
    out.origin_far[axis] = up ? o_lo[axis] : o_hi[axis];
    out.inverse_lo[axis] = i_lo[axis];
    out.inverse_hi[axis] = i_hi[axis];
  }
  if (!(t_lo <= t_hi)) return false;
  out.t_lo = t_lo;
  out.t_hi = t_hi;
  return true;
}

#if defined(__SSE2__)

// Bit k set where child slot k may be hit by some lane of the packet.
inline std::uint32_t interval_test_8(const OctreeNode& node, const PacketInterval& packet) {
  std::uint32_t mask = 0;
  for (int first = 0; first < 8; first += 4) {
    __m128 enter = _mm_set1_ps(packet.t_lo);
    __m128 exit = _mm_set1_ps(packet.t_hi);
    for (int axis = 0; axis < 3; ++axis) {
      const __m128 i_lo = _mm_set1_ps(packet.inverse_lo[axis]);
      const __m128 i_hi = _mm_set1_ps(packet.inverse_hi[axis]);
      const __m128 margin = _mm_set1_ps(packet.margin[axis]);
      const __m128 near = _mm_sub_ps(_mm_loadu_ps((node.*packet.near_plane[axis]) + first),
                                     _mm_set1_ps(packet.origin_near[axis]));
      const __m128 far = _mm_sub_ps(_mm_loadu_ps((node.*packet.far_plane[axis]) + first),
                                    _mm_set1_ps(packet.origin_far[axis]));
      enter = _mm_max_ps(
          enter, _mm_sub_ps(_mm_min_ps(_mm_mul_ps(near, i_lo), _mm_mul_ps(near, i_hi)), margin));
      exit = _mm_min_ps(
          exit, _mm_add_ps(_mm_max_ps(_mm_mul_ps(far, i_lo), _mm_mul_ps(far, i_hi)), margin));
    }
    mask |= static_cast<std::uint32_t>(_mm_movemask_ps(_mm_cmple_ps(enter, exit))) << first;
  }
  return mask;
}

#else

inline std::uint32_t interval_test_8(const OctreeNode& node, const PacketInterval& packet) {
  std::uint32_t mask = 0;
  for (int k = 0; k < 8; ++k) {
    float enter = packet.t_lo, exit = packet.t_hi;
    for (int axis = 0; axis < 3; ++axis) {
      const float near = (node.*packet.near_plane[axis])[k] - packet.origin_near[axis];
      const float far = (node.*packet.far_plane[axis])[k] - packet.origin_far[axis];
      enter =
          std::max(enter, std::min(near * packet.inverse_lo[axis], near * packet.inverse_hi[axis]) -
                              packet.margin[axis]);
      exit = std::min(exit, std::max(far * packet.inverse_lo[axis], far * packet.inverse_hi[axis]) +
                                packet.margin[axis]);
    }
    mask |= static_cast<std::uint32_t>(enter <= exit) << k;
  }
  return mask;
}

#endif

}  // namespace occlusion::octree_detail
