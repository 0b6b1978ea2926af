#pragma once
// Points in Morton order (morton.hpp's codes over the cube around them).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace occlusion {

// The indices of `positions` in Morton order of their cells in the cube
// around them (ties in index order): neighbours in the order are neighbours
// in space. Consecutive kd-tree queries then read the same points (a cloud in
// random order took twice as long as the same cloud sorted), and one
// viewpoint's rays to consecutive points point nearly the same way. Sorted
// on `threads` threads (0 = all cores); the order does not depend on them.
std::vector<std::uint32_t> morton_order(const std::vector<Eigen::Vector3f>& positions,
                                        unsigned threads = 0);

}  // namespace occlusion
