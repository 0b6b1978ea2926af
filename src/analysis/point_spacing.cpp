#include "occlusion/analysis/point_spacing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "quantiles.hpp"

namespace occlusion {

std::size_t spacing_stride(std::size_t points) {
  return std::max<std::size_t>(1, points / kSpacingSamples);
}

double same_position_distance(const Eigen::Vector3f& p) {
  return 1e-6 * std::max(1.0, static_cast<double>(p.cwiseAbs().maxCoeff()));
}

std::optional<PointSpacing> spacing_from(const std::vector<DistinctNeighbour>& answers) {
  PointSpacing result;
  std::vector<double> distances;
  for (const DistinctNeighbour& neighbour : answers) {
    result.duplicate_hits += neighbour.coincident >= 2 ? 1 : 0;
    if (neighbour.coincident < kSpacingNeighbours && std::isfinite(neighbour.nearest_squared)) {
      distances.push_back(std::sqrt(static_cast<double>(neighbour.nearest_squared)));
    }
  }
  if (distances.empty()) return std::nullopt;
  result.samples = distances.size();
  const std::vector<double> q = quantiles::in_place(distances, {0.5, 0.1, 0.9});
  result.spacing = q[0];
  result.quantile_10 = q[1];
  result.quantile_90 = q[2];
  return result;
}

PointSpacing measure_point_spacing(const PointCloud& cloud, unsigned threads) {
  if (cloud.size() < 2) {
    throw std::invalid_argument("point spacing: the cloud needs at least two points");
  }
  const std::size_t stride = spacing_stride(cloud.size());
  std::vector<std::size_t> samples;
  std::vector<double> same;
  for (std::size_t i = 0; i < cloud.size(); i += stride) {
    samples.push_back(i);
    same.push_back(same_position_distance(cloud.positions[i]));
  }
  // A kd-tree's k nearest (k = kSpacingNeighbours, the sample itself among
  // them): the first beyond `same` is the nearest distinct neighbour, unless
  // all k are within it; any of them but the sample itself makes a duplicate.
  const std::optional<PointSpacing> spacing = spacing_from(
      distinct_neighbours(cloud.positions, samples, same, kSpacingNeighbours, threads));
  if (!spacing) {
    throw std::invalid_argument(
        "point spacing: no point has a neighbour at a distinct position (all points coincide?)");
  }
  return *spacing;
}

}  // namespace occlusion
