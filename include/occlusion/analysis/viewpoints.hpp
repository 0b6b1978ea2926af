#pragma once
// The seed's viewpoint patterns (thesis section 5.1, figure 5.2).
//
// From the scene's axis-aligned bounding box [lo, hi] with centre c:
//   C = c                      (centre)
//   U = (c + hi) / 2           (midpoint between centre and the max corner)
//   L = (c + lo) / 2           (midpoint between centre and the min corner)
// Patterns, numbered by how many viewpoints they use (so that the seed's
// table 5.1 reads: 1 = one viewpoint ... 7 = all three):
//   1: C      2: U      3: L
//   4: C, U   5: C, L   6: U, L
//   7: C, U, L

#include <Eigen/Core>
#include <string>
#include <vector>

namespace occlusion {

inline constexpr int kMinPattern = 1;
inline constexpr int kMaxPattern = 7;

// Throws std::invalid_argument for a pattern outside 1..7 or an empty/non-finite box.
std::vector<Eigen::Vector3d> pattern_viewpoints(int pattern, const Eigen::Vector3d& lo,
                                                const Eigen::Vector3d& hi);
// Names of the pattern's viewpoints in order ("centre", "max_mid", "min_mid").
std::vector<std::string> pattern_viewpoint_names(int pattern);

}  // namespace occlusion

namespace occlusion {

// `count` viewpoints placed reproducibly inside the box [lo, hi], up being
// coordinate axis `up_axis` (2 = z, the default): an nx x ny grid at
// mid-height over the middle 80% of the floor plan, whose axes are the next
// two in cyclic order (x, y under z up; z, x under y up), with nx x ny the
// smallest near-square grid holding `count`, filled row by row.
// Throws std::invalid_argument for count == 0, an empty box or an axis not 0..2.
std::vector<Eigen::Vector3d> grid_viewpoints(std::size_t count, const Eigen::Vector3d& lo,
                                             const Eigen::Vector3d& hi, int up_axis = 2);

}  // namespace occlusion
