#include "occlusion/analysis/distinct_neighbours.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/morton_knn.hpp"
#include "occlusion/core/parallel.hpp"

namespace occlusion {

namespace {

// A distance found within h is trusted only below h x (1 - kMargin): the cell
// of a point is a rounded quotient, so a point just within h of a query could
// sit two cells away from it.
constexpr double kMargin = 1e-3;
// Each pass that leaves queries unanswered multiplies the cell size by this.
constexpr double kGrowth = 4.0;

using Cell = std::array<std::int64_t, 3>;

// The grid of one pass: cells of size h from `origin`.
struct Grid {
  Eigen::Vector3d origin;
  double h = 0.0;
  std::uint64_t mask = 0;  // buckets - 1

  Cell cell_of(const Eigen::Vector3f& p) const {
    return {static_cast<std::int64_t>(std::floor((p.x() - origin.x()) / h)),
            static_cast<std::int64_t>(std::floor((p.y() - origin.y()) / h)),
            static_cast<std::int64_t>(std::floor((p.z() - origin.z()) / h))};
  }
  // Different cells may share a bucket: a point is then compared with
  // queries that are not near it, which costs time, never an answer.
  std::uint64_t bucket_of(const Cell& c) const {
    std::uint64_t k = static_cast<std::uint64_t>(c[0]) * 0x9E3779B97F4A7C15ull;
    k ^= static_cast<std::uint64_t>(c[1]) * 0xC2B2AE3D27D4EB4Full;
    k ^= static_cast<std::uint64_t>(c[2]) * 0x165667B19E3779F9ull;
    k ^= k >> 29;
    return k & mask;
  }
};

// The queries of each bucket, as offsets into one list (no query twice in a bucket).
struct Buckets {
  LargeVector<std::uint32_t> begin;  // buckets + 1 offsets
  LargeVector<std::uint32_t> entries;
  std::vector<std::uint64_t> occupied;  // one bit per bucket
};

Buckets fill_buckets(const Grid& grid, const std::vector<Eigen::Vector3f>& points) {
  // Counted, then placed (a counting sort by bucket): the queries of a bucket
  // come in increasing order, as a sort of (bucket, query) pairs would put
  // them, without sorting 27 pairs a query.
  const std::size_t count = static_cast<std::size_t>(grid.mask) + 1;
  Buckets buckets;
  buckets.begin.assign(count + 1, 0);
  buckets.occupied.assign((count + 63) / 64, 0);
  // The distinct buckets of the 27 cells around query q (two cells may share one).
  std::array<std::uint64_t, 27> around{};
  const auto buckets_around = [&](std::size_t q) {
    const Cell c = grid.cell_of(points[q]);
    std::size_t n = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          around[n++] = grid.bucket_of({c[0] + dx, c[1] + dy, c[2] + dz});
        }
      }
    }
    std::sort(around.begin(), around.end());
    return static_cast<std::size_t>(std::unique(around.begin(), around.end()) - around.begin());
  };
  std::size_t entries = 0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    const std::size_t n = buckets_around(q);
    for (std::size_t j = 0; j < n; ++j) ++buckets.begin[around[j] + 1];
    entries += n;
  }
  for (std::size_t b = 0; b < count; ++b) buckets.begin[b + 1] += buckets.begin[b];
  buckets.entries.resize(entries);
  // Each bucket's offset moves on as it is filled, to its end, the next
  // bucket's beginning; shifted back by one bucket after.
  for (std::size_t q = 0; q < points.size(); ++q) {
    const std::size_t n = buckets_around(q);
    for (std::size_t j = 0; j < n; ++j) {
      const std::uint64_t bucket = around[j];
      buckets.entries[buckets.begin[bucket]++] = static_cast<std::uint32_t>(q);
      buckets.occupied[bucket / 64] |= std::uint64_t{1} << (bucket % 64);
    }
  }
  std::copy_backward(buckets.begin.begin(), buckets.begin.end() - 1, buckets.begin.end());
  buckets.begin[0] = 0;
  return buckets;
}

// One pass over the cloud for the queries at `points` (with `same`): each
// query's coincident count and nearest squared distance beyond `same`.
std::vector<DistinctNeighbour> one_pass(const std::vector<Eigen::Vector3f>& positions,
                                        const Grid& grid,
                                        const std::vector<Eigen::Vector3f>& points,
                                        const std::vector<double>& same, unsigned threads) {
  const Buckets buckets = fill_buckets(grid, points);
  const std::size_t n = positions.size();
  const unsigned parts = std::max(
      1u, std::min<unsigned>(resolve_thread_count(threads), static_cast<unsigned>(n / 65536 + 1)));
  std::vector<std::vector<DistinctNeighbour>> found(
      parts, std::vector<DistinctNeighbour>(
                 points.size(), DistinctNeighbour{0, std::numeric_limits<float>::infinity()}));
  parallel_for(parts, 1, parts, [&](std::size_t first, std::size_t last) {
    for (std::size_t part = first; part < last; ++part) {
      std::vector<DistinctNeighbour>& mine = found[part];
      for (std::size_t i = n * part / parts; i < n * (part + 1) / parts; ++i) {
        const Eigen::Vector3f& p = positions[i];
        const std::uint64_t b = grid.bucket_of(grid.cell_of(p));
        if (!(buckets.occupied[b / 64] >> (b % 64) & 1u)) continue;
        for (std::uint32_t e = buckets.begin[b]; e < buckets.begin[b + 1]; ++e) {
          const std::uint32_t q = buckets.entries[e];
          mine[q].offer(knn_squared_distance(points[q], p), same[q]);
        }
      }
    }
  });
  std::vector<DistinctNeighbour> merged = std::move(found[0]);
  for (unsigned part = 1; part < parts; ++part) {
    for (std::size_t q = 0; q < merged.size(); ++q) {
      merged[q].coincident += found[part][q].coincident;
      merged[q].nearest_squared =
          std::min(merged[q].nearest_squared, found[part][q].nearest_squared);
    }
  }
  return merged;
}

// The box of the middle 98% of the queries along each axis: the queries are
// a sample of the cloud, so stray points far outside a room do not stretch it.
// A first cell sized from the whole box would put most of the room in one cell,
// and every point of it would be compared with every query there (one stray
// point 10 km off made a 1M-point cloud 25 times slower).
Eigen::Vector3d robust_extent(const std::vector<Eigen::Vector3f>& positions,
                              const std::vector<std::size_t>& queries) {
  Eigen::Vector3d extent;
  std::vector<float> values(queries.size());
  const std::size_t low = queries.size() / 100;
  const std::size_t high = queries.size() - 1 - low;
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t k = 0; k < queries.size(); ++k) values[k] = positions[queries[k]][axis];
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(low),
                     values.end());
    const double lo = values[low];
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(high),
                     values.end());
    extent[axis] = static_cast<double>(values[high]) - lo;
  }
  return extent;
}

// A first cell size near the mean spacing of a cloud sampling the surfaces
// of its box (a room); later passes grow it where that was too small.
double first_cell_size(const Eigen::Vector3d& extent, std::size_t n, double largest_same) {
  const double area =
      2.0 * (extent.x() * extent.y() + extent.y() * extent.z() + extent.z() * extent.x());
  const double per_point = std::sqrt(area / static_cast<double>(n));
  const double along = extent.norm() / static_cast<double>(n);
  return std::max({per_point, along, 4.0 * largest_same});
}

}  // namespace

std::vector<DistinctNeighbour> distinct_neighbours(const std::vector<Eigen::Vector3f>& positions,
                                                   const std::vector<std::size_t>& queries,
                                                   const std::vector<double>& same,
                                                   std::uint32_t cap, unsigned threads) {
  if (queries.size() != same.size()) {
    throw std::invalid_argument("distinct neighbours: one `same` distance per query is needed");
  }
  if (queries.size() >= std::numeric_limits<std::uint32_t>::max() / 27) {
    throw std::invalid_argument("distinct neighbours: too many queries");
  }
  std::vector<DistinctNeighbour> answers(queries.size());
  if (queries.empty()) return answers;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3f& p : positions) {
    if (!p.allFinite())
      throw std::invalid_argument("distinct neighbours: a position is not finite");
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  double largest_same = 0.0;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    if (queries[k] >= positions.size()) {
      throw std::invalid_argument("distinct neighbours: a query index is out of range");
    }
    largest_same = std::max(largest_same, same[k]);
  }
  const double diagonal = (hi - lo).norm();

  Grid grid;
  grid.origin = lo;
  grid.h = first_cell_size(robust_extent(positions, queries), positions.size(), largest_same);
  std::vector<std::size_t> open(queries.size());  // unanswered: indices into `queries`
  for (std::size_t k = 0; k < open.size(); ++k) open[k] = k;
  while (!open.empty()) {
    // Once h x (1 - margin) spans the whole box, every point is within reach.
    const bool spans_all = grid.h * (1.0 - kMargin) > diagonal;
    std::vector<Eigen::Vector3f> points;
    std::vector<double> open_same;
    for (const std::size_t k : open) {
      points.push_back(positions[queries[k]]);
      open_same.push_back(same[k]);
    }
    std::uint64_t buckets = 1024;
    while (buckets < 2 * 27 * points.size()) buckets *= 2;
    grid.mask = buckets - 1;
    const std::vector<DistinctNeighbour> pass =
        one_pass(positions, grid, points, open_same, threads);
    std::vector<std::size_t> still_open;
    const double trusted = grid.h * (1.0 - kMargin);
    for (std::size_t j = 0; j < open.size(); ++j) {
      const DistinctNeighbour& a = pass[j];
      const bool answered = spans_all || a.coincident >= cap ||
                            std::sqrt(static_cast<double>(a.nearest_squared)) <= trusted;
      if (answered) {
        // As a kd-tree's `cap` nearest: all within `same`, none beyond.
        answers[open[j]] = {
            std::min(a.coincident, cap),
            a.coincident >= cap ? std::numeric_limits<float>::infinity() : a.nearest_squared};
      } else {
        still_open.push_back(open[j]);
      }
    }
    open.swap(still_open);
    grid.h *= kGrowth;
  }
  return answers;
}

}  // namespace occlusion
