#include "occlusion/analysis/point_spacing.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace occlusion {

namespace {

// Neighbours asked for per query: a point stored k times has k - 1 neighbours
// at distance 0 before the first distinct one.
constexpr int kNeighbours = 8;

// Positions closer than this (relative to their magnitude, floats) are one position.
double same_position_distance(const Eigen::Vector3f& p) {
  return 1e-6 * std::max(1.0, static_cast<double>(p.cwiseAbs().maxCoeff()));
}

double quantile(std::vector<double>& values, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

PointSpacing measure_point_spacing(const PointCloud& cloud) {
  if (cloud.size() < 2) {
    throw std::invalid_argument("point spacing: the cloud needs at least two points");
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  points->reserve(cloud.size());
  for (const auto& p : cloud.positions) points->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(points);

  PointSpacing result;
  const std::size_t stride = std::max<std::size_t>(1, cloud.size() / kSpacingSamples);
  std::vector<double> distances;
  pcl::Indices nearest(kNeighbours);
  std::vector<float> squared(kNeighbours);
  for (std::size_t i = 0; i < cloud.size(); i += stride) {
    const int found = tree.nearestKSearch((*points)[i], kNeighbours, nearest, squared);
    const double same = same_position_distance(cloud.positions[i]);
    bool duplicate = false;
    for (int k = 0; k < found; ++k) {
      const double distance = std::sqrt(static_cast<double>(squared[static_cast<std::size_t>(k)]));
      if (distance <= same) {
        duplicate = duplicate || nearest[static_cast<std::size_t>(k)] != static_cast<int>(i);
        continue;
      }
      distances.push_back(distance);
      break;
    }
    result.duplicate_hits += duplicate ? 1 : 0;
  }
  if (distances.empty()) {
    throw std::invalid_argument(
        "point spacing: no point has a neighbour at a distinct position (all points coincide?)");
  }
  result.samples = distances.size();
  result.spacing = quantile(distances, 0.5);
  result.quantile_10 = quantile(distances, 0.1);
  result.quantile_90 = quantile(distances, 0.9);
  return result;
}

}  // namespace occlusion
