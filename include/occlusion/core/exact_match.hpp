#pragma once
// Pairs two lists of the same points given in different orders by identical
// coordinates, so that data stored in one order (a label file following an
// S3DIS room's <room>.txt, a prediction cloud written in its own order) can be
// verified to belong to points stored in another. No tolerance: the same point
// read from the same text twice has the same float coordinates; anything else
// is a different point. Duplicated points (real scans store many points twice)
// pair in their order of appearance; a point with a non-finite coordinate
// pairs with none.

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <vector>

namespace occlusion {

struct ExactMatch {
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  // source_of[i]: the index in `source` of target point i, or kNone when no
  // source point with its coordinates is left.
  std::vector<std::size_t> source_of;
  std::size_t unmatched_targets = 0;
  std::size_t first_unmatched_target = kNone;  // the lowest such target index
  std::size_t unmatched_sources = 0;           // source points no target took

  // Every target has its own source and every source is used: the two lists
  // hold the same points (as a multiset).
  bool complete() const { return unmatched_targets == 0 && unmatched_sources == 0; }
};

// O(n log n) time and two index arrays of memory (sorts, no hashing, so a
// room of millions of points costs no more than its copy).
ExactMatch match_exact_points(const std::vector<Eigen::Vector3f>& source,
                              const std::vector<Eigen::Vector3f>& target);

}  // namespace occlusion
