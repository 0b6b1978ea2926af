#pragma once
// The spacing of a point cloud, from which the point radius is chosen
// ("auto"). Spacing = the median, over a fixed stride sample of the points,
// of each sampled point's distance to its nearest neighbour at a distinct
// position. Why:
// - distinct positions: real scans often store every point twice (two passes,
//   merged frames); a zero distance says nothing about the gaps rays see.
// - the median: spacing grows with the distance from the scanner, and stray
//   points far outside the room have huge gaps; the median is the gap of the
//   typical point and ignores both tails.
// - a stride sample (every k-th point, k = max(1, points / kSpacingSamples),
//   so up to 2 x kSpacingSamples queries): deterministic without a seed.
//   The answers are a kd-tree's k nearest neighbours, exactly, found without
//   a tree over the whole cloud (distinct_neighbours.hpp): streaming 16M
//   points past the samples costs a fraction of building the tree.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "occlusion/analysis/distinct_neighbours.hpp"
#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

inline constexpr std::size_t kSpacingSamples = 20000;
// Neighbours asked for per sample: a point stored k times has k - 1
// neighbours at distance 0 before the first distinct one.
inline constexpr std::uint32_t kSpacingNeighbours = 8;

struct PointSpacing {
  double spacing = 0.0;            // median nearest distinct-neighbour distance
  double quantile_10 = 0.0;        // 10th percentile of the same distances
  double quantile_90 = 0.0;        // 90th percentile
  std::size_t samples = 0;         // points whose distance was measured
  std::size_t duplicate_hits = 0;  // sampled points with a neighbour at the same position
};

// Throws std::invalid_argument when the cloud has fewer than two distinct
// positions. `threads`: 0 = all cores.
PointSpacing measure_point_spacing(const PointCloud& cloud, unsigned threads = 0);

// The sample: points 0, stride, 2 stride, ... of a cloud of `points`.
std::size_t spacing_stride(std::size_t points);
// Positions closer than this to p (relative to its magnitude, floats) are one position.
double same_position_distance(const Eigen::Vector3f& p);
// The spacing from the sample's answers (distinct_neighbours' with cap
// kSpacingNeighbours, in sample order), as measure_point_spacing gives it
// (which a search that already knows each sample's kSpacingNeighbours
// nearest can skip); empty when no sample has a distinct neighbour.
std::optional<PointSpacing> spacing_from(const std::vector<DistinctNeighbour>& answers);

}  // namespace occlusion

namespace occlusion {

// A request's point_radius "auto" (the default): NaN, since every number a
// user can give (0, negative) must stay an error; test it with is_auto_radius.
inline constexpr double kAutoPointRadius = std::numeric_limits<double>::quiet_NaN();
inline bool is_auto_radius(double radius) {
  return std::isnan(radius);
}

// point_radius "auto" = a factor x spacing, by what the radius must do.
// A scan (-fscan) must not let neighbours hide each other. Seen from a
// sensor, the ray to a pixel's point passes a neighbouring pixel's point at
// (its depth) x (the pixel angle), and the spacing grows the same way with
// depth, so the median spacing is about (median depth) x (pixel angle). A
// radius of a quarter of it keeps every point closer than a quarter of the
// median depth from hiding its neighbours (a Kinect frame: from 0.5 m when
// the median is 2 m), and rays still meet the surface in their own pixel.
inline constexpr double kScanRadiusPerSpacing = 0.25;
// Light-source rays (-poc) must not slip between the points of a surface:
// spacing / sqrt(2) closes a surface sampled on a square grid of that spacing
// (half the grid's diagonal); surfaces sampled more sparsely than the median
// (far from a scanner) can still let rays through.
inline constexpr double kTracingRadiusPerSpacing = 0.70710678118654752;

// An explicit radius outside [kLowRadiusPerSpacing, kHighRadiusPerSpacing] x
// spacing is far from the cloud's spacing (warned about by the jobs).
inline constexpr double kLowRadiusPerSpacing = 0.25;
inline constexpr double kHighRadiusPerSpacing = 2.0;

// The radius a job traced with and the spacing it was judged against.
struct PointRadius {
  double radius = 0.0;
  bool automatic = false;  // chosen from the spacing
  PointSpacing spacing;    // all zero when the cloud has too few distinct points
};

}  // namespace occlusion
