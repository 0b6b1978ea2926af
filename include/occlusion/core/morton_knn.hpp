#pragma once
// Exact k nearest neighbours of points already in Morton order
// (morton_order.hpp), without a copy of them: a complete binary tree over the
// array's index ranges (each node a contiguous run of the Morton curve, so a
// box of nearby points), of which only the boxes are stored (about 1.5 bytes
// a point: leaves of 16 to 31 points).
//
// Queries come in index order, so consecutive ones share a leaf: the points
// within a radius r of the leaf's box are gathered once, and each query of
// the leaf takes its k nearest among them, first among those within 1.2 times
// the k-th distance of the query before when at least k are (the same density
// a step away), else within the farthest of that query's k neighbours from
// this one (k points, so never fewer; any bound that holds k points gives
// the same k nearest). The distances to the gathered points and the packing
// of those within the bound go eight at a time in AVX2 where the CPU has it
// (knn_candidates.hpp, the same bits). Its answer is certain when its
// k-th distance is below r plus its own distance to the box's faces (a point
// left out is farther than that); r follows the k-th distances of the leaf
// before. A query that is not certain (too few points within reach: a stray
// point, the edge of a sparse region) and every query of a leaf whose box is
// far wider than r (a run of the curve that jumps) search the tree on their
// own, depth first, pruned by the boxes. Density that varies a hundredfold
// across a scan is followed leaf by leaf; nothing is sized from a global cell.
//
// The answer is the k smallest (squared distance, index) pairs, nearest first,
// with distances summed as FLANN's L2_Simple<float> sums them: ties are broken
// by index, so the answer depends on nothing but the points.
//
// Standard library and Eigen only.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "occlusion/core/large_buffer.hpp"

namespace occlusion {

// The squared distance as FLANN's L2_Simple<float> sums it, term by term in
// float: every neighbour search here sums it so, so their ties agree.
inline float knn_squared_distance(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const float dx = a.x() - b.x();
  const float dy = a.y() - b.y();
  const float dz = a.z() - b.z();
  float sum = dx * dx;
  sum += dy * dy;
  sum += dz * dz;
  return sum;
}

class MortonKnn {
 public:
  // A query's neighbours: ids[0..got), nearest first (the query among them).
  using Visit = std::function<void(std::size_t n, std::size_t query, const std::uint32_t* ids,
                                   std::size_t got)>;

  // points[0..count) in Morton order, borrowed: they must outlive the search
  // and stay unchanged. At most 2^32 - 1 points, all finite.
  MortonKnn(const Eigen::Vector3f* points, std::size_t count, unsigned threads = 0);
  template <class Allocator>
  explicit MortonKnn(const std::vector<Eigen::Vector3f, Allocator>& points, unsigned threads = 0)
      : MortonKnn(points.data(), points.size(), threads) {}

  // For n in [first, last): the query is subset[n] (null: n itself), the
  // subset increasing; calls visit(n, query, ids, got) with its min(k, size)
  // nearest. Thread-safe: each thread may search its own range (visit must
  // not search again: the thread's scratch holds the answer it reads).
  void search(const std::uint32_t* subset, std::size_t first, std::size_t last, std::size_t k,
              const Visit& visit) const;

  std::size_t size() const { return count_; }

 private:
  struct Box {
    Eigen::Vector3f lo, hi;
  };
  struct Scratch;

  std::size_t begin_of(int depth, std::size_t j) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(count_) * j) >> depth);
  }
  void gather(const Box& around, float radius, Scratch& scratch) const;
  void select_nearest(float guess, std::size_t k, Scratch& scratch) const;
  void search_alone(const Eigen::Vector3f& query, std::size_t k, float bound,
                    Scratch& scratch) const;

  const Eigen::Vector3f* points_;
  std::size_t count_;
  int depth_ = 0;           // of the leaves: 2^depth_ of them
  LargeVector<Box> boxes_;  // node i at depth d, rank j: i = 2^d - 1 + j
  float margin_ = 0.0f;     // float rounding of distances at the cloud's coordinates
};

}  // namespace occlusion
