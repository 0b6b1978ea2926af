#pragma once
// Exact nearest-neighbour answers for a few query points of a large cloud,
// without a search structure over the whole cloud: what point_spacing needs
// from millions of points is the neighbourhood of some thousands of them.
//
// For each query point q (an index into the positions) and its distance
// `same[q]` (closer points are one position with it), the answer holds
// - coincident: how many points lie within `same` of q, q itself included;
// - nearest_squared: the smallest squared distance beyond `same`; infinity
//   when every point lies within it, or `cap` points do (as a kd-tree's
//   `cap` nearest neighbours would say).
// Distances are those a float kd-tree (FLANN's L2_Simple, as PCL uses it)
// computes: the squared distance summed in float, x then y then z; a point
// lies within `same` when the square root of that float, in double, is at
// most `same`. So the answers equal a kd-tree's, bit for bit.
//
// How: the query points are entered into a hashed grid of cell size h, each
// into the 27 cells around its own; the cloud is streamed once (on all cores)
// and each point is compared only with the queries of its cell's bucket. A
// query whose nearest distinct point lies within h, or that has `cap`
// coincident points, is answered exactly (every point within h of it lies in
// those 27 cells); the others go round again with h four times larger, until
// h spans the whole cloud. Memory: a few arrays per query, none per point.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace occlusion {

struct DistinctNeighbour {
  std::uint32_t coincident = 0;  // capped at the `cap` asked for
  float nearest_squared = 0.0f;  // infinity: no point beyond `same`

  // One more point, `squared` (knn_squared_distance) from the query: the
  // rule above, in one place for every search that answers it.
  void offer(float squared, double same) {
    if (std::sqrt(static_cast<double>(squared)) <= same) {
      ++coincident;
    } else if (squared < nearest_squared) {
      nearest_squared = squared;
    }
  }
};

// Throws std::invalid_argument when a query index is out of range, the sizes
// of `queries` and `same` differ, or a position is not finite. `threads`: 0 = all cores.
std::vector<DistinctNeighbour> distinct_neighbours(const std::vector<Eigen::Vector3f>& positions,
                                                   const std::vector<std::size_t>& queries,
                                                   const std::vector<double>& same,
                                                   std::uint32_t cap, unsigned threads = 0);

}  // namespace occlusion
