#include "occlusion/analysis/point_spacing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "occlusion/analysis/distinct_neighbours.hpp"
#include "quantiles.hpp"

namespace occlusion {

namespace {

// Neighbours asked for per query: a point stored k times has k - 1 neighbours
// at distance 0 before the first distinct one.
constexpr std::uint32_t kNeighbours = 8;

// Positions closer than this (relative to their magnitude, floats) are one position.
double same_position_distance(const Eigen::Vector3f& p) {
  return 1e-6 * std::max(1.0, static_cast<double>(p.cwiseAbs().maxCoeff()));
}

}  // namespace

PointSpacing measure_point_spacing(const PointCloud& cloud) {
  if (cloud.size() < 2) {
    throw std::invalid_argument("point spacing: the cloud needs at least two points");
  }
  const std::size_t stride = std::max<std::size_t>(1, cloud.size() / kSpacingSamples);
  std::vector<std::size_t> samples;
  std::vector<double> same;
  for (std::size_t i = 0; i < cloud.size(); i += stride) {
    samples.push_back(i);
    same.push_back(same_position_distance(cloud.positions[i]));
  }
  // A kd-tree's k nearest (k = kNeighbours, the sample itself among them):
  // the first beyond `same` is the nearest distinct neighbour, unless all k
  // are within it; any of them but the sample itself makes a duplicate.
  const std::vector<DistinctNeighbour> found =
      distinct_neighbours(cloud.positions, samples, same, kNeighbours);

  PointSpacing result;
  std::vector<double> distances;
  for (const DistinctNeighbour& neighbour : found) {
    result.duplicate_hits += neighbour.coincident >= 2 ? 1 : 0;
    if (neighbour.coincident < kNeighbours && std::isfinite(neighbour.nearest_squared)) {
      distances.push_back(std::sqrt(static_cast<double>(neighbour.nearest_squared)));
    }
  }
  if (distances.empty()) {
    throw std::invalid_argument(
        "point spacing: no point has a neighbour at a distinct position (all points coincide?)");
  }
  result.samples = distances.size();
  const std::vector<double> q = quantiles::in_place(distances, {0.5, 0.1, 0.9});
  result.spacing = q[0];
  result.quantile_10 = q[1];
  result.quantile_90 = q[2];
  return result;
}

}  // namespace occlusion
