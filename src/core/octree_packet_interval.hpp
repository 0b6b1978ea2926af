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

#include "occlusion/core/octree.hpp"

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

// A packet's extremes over its live lanes, per axis: origins, inverse
// directions, and the t interval.
struct PacketBounds {
  float origin_lo[3], origin_hi[3];
  float inverse_lo[3], inverse_hi[3];
  float t_lo, t_hi;
};

// The interval of a packet with these bounds; false if it cannot cull
// (directions of mixed signs, non-finite or extreme values, no live lane).
inline bool make_packet_interval(const PacketBounds& bounds, float scene_magnitude,
                                 PacketInterval& out) {
  for (int axis = 0; axis < 3; ++axis) {
    const float i_lo = bounds.inverse_lo[axis], i_hi = bounds.inverse_hi[axis];
    const float o_lo = bounds.origin_lo[axis], o_hi = bounds.origin_hi[axis];
    const bool up = i_lo > 0.0f;
    if (!(up || i_hi < 0.0f)) return false;  // mixed signs, or NaN
    const float i_mag = std::max(std::fabs(i_lo), std::fabs(i_hi));
    const float o_mag = std::max(std::fabs(o_lo), std::fabs(o_hi));
    if (!(i_mag < kIntervalLimit && o_mag < kIntervalLimit)) return false;
    // 2^-20 relative: eight times the rounding of (near - o) * i plus that of
    // a lane's near * i - o * i, both at most a few ulps of (|near| + |o|) |i|.
    out.margin[axis] = 0x1p-20f * (scene_magnitude + o_mag) * i_mag;
    if (!std::isfinite(out.margin[axis])) return false;
    out.near_plane[axis] = up ? kLowerPlane[axis] : kUpperPlane[axis];
    out.far_plane[axis] = up ? kUpperPlane[axis] : kLowerPlane[axis];
    // Entry (near - o) * i is smallest at the largest o going up, the
    // smallest o going down; the exit is largest at the opposite end.
    out.origin_near[axis] = up ? o_hi : o_lo;
    out.origin_far[axis] = up ? o_lo : o_hi;
    out.inverse_lo[axis] = i_lo;
    out.inverse_hi[axis] = i_hi;
  }
  // Also false with no live lane: +inf <= -inf fails.
  if (!(bounds.t_lo <= bounds.t_hi)) return false;
  out.t_lo = bounds.t_lo;
  out.t_hi = bounds.t_hi;
  return true;
}

}  // namespace occlusion::octree_detail
