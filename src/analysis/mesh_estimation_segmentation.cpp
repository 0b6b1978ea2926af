// Region growing as the seed does it with PCL's RegionGrowing (listing 4.7),
// over the neighbour lists find_neighbourhoods kept, with PCL's semantics
// step for step (pcl/segmentation/impl/region_growing.hpp, smooth mode, no
// residual test):
// - seeds are taken in the order std::sort leaves the (curvature, index)
//   pairs in under PCL's comparePair (curvature only), the next seed being
//   the first point not yet in a region;
// - a region grows breadth-first: a point not yet in a region joins from a
//   neighbour already in it when |n . n'| >= cos(smoothness), and grows the
//   region further only if its curvature is not above curvature_threshold;
// - every region is grown, since the points of a region dropped as too small
//   are in no later region either; only the regions within the size limits
//   become clusters, each with its points in index order.
// What PCL stores per region (an index list for each of the ~100,000 dropped
// regions of a large scan) and per point (a vector of neighbours) is not.

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "mesh_estimation_stages.hpp"

namespace occlusion::mesh_estimation {

namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

RegionSizes measure(const std::vector<std::size_t>& region_sizes,
                    const RegionGrowingOptions& options) {
  RegionSizes sizes;
  for (const std::size_t points : region_sizes) {
    ++sizes.regions;
    sizes.largest = std::max(sizes.largest, points);
    if (points < options.min_cluster_size) {
      ++sizes.too_small;
      sizes.too_small_points += points;
    } else if (points > options.max_cluster_size) {
      ++sizes.too_large;
      sizes.too_large_points += points;
    }
  }
  return sizes;
}

}  // namespace

Segmentation grow_regions(const Neighbourhoods& hoods, const RegionGrowingOptions& options,
                          const Progress& progress) {
  const std::size_t count = hoods.normals.size();
  // As PCL computes them: the angle as float, its cosine in float.
  const float cosine_threshold =
      std::cos(static_cast<float>(options.smoothness_degrees * kDegrees));
  const auto curvature_threshold = static_cast<float>(options.curvature_threshold);

  progress("region growing", 0.0);
  // The seed order: indices sorted by curvature alone, as PCL's comparePair
  // sorts its (curvature, index) pairs. std::sort moves elements by the
  // comparisons' outcomes only, and those are the same, so the order is the
  // same; without the pairs this stage (which sets -rgoc's peak) takes 4
  // bytes a point less.
  std::vector<int> seeds(count);
  for (std::size_t i = 0; i < count; ++i) seeds[i] = static_cast<int>(i);
  const std::vector<float>& curvatures = hoods.curvatures;
  std::sort(seeds.begin(), seeds.end(), [&curvatures](int a, int b) {
    return curvatures[static_cast<std::size_t>(a)] < curvatures[static_cast<std::size_t>(b)];
  });

  std::vector<std::int32_t> region(count, -1);
  std::vector<std::size_t> region_sizes;
  std::vector<pcl::index_t> queue;  // grows to the largest region's front
  std::size_t grown = 0;
  std::size_t next_seed = 0;
  while (grown < count) {
    while (region[static_cast<std::size_t>(seeds[next_seed])] != -1) ++next_seed;
    const auto id = static_cast<std::int32_t>(region_sizes.size());
    const auto seed = static_cast<std::size_t>(seeds[next_seed]);
    queue.assign(1, static_cast<pcl::index_t>(seed));
    region[seed] = id;
    std::size_t size = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto current = static_cast<std::size_t>(queue[head]);
      const Eigen::Vector3f& normal = hoods.normals[current];
      hoods.lists.for_each(current, [&](std::int32_t neighbour) {
        const auto other = static_cast<std::size_t>(neighbour);
        if (region[other] != -1) return;
        if (std::abs(hoods.normals[other].dot(normal)) < cosine_threshold) return;
        region[other] = id;
        ++size;
        if (!(hoods.curvatures[other] > curvature_threshold)) queue.push_back(neighbour);
      });
    }
    region_sizes.push_back(size);
    grown += size;
    if ((region_sizes.size() & 0xffff) == 0) progress.check_cancel();
  }

  std::vector<int>().swap(seeds);
  std::vector<pcl::index_t>().swap(queue);

  Segmentation segmentation;
  segmentation.regions = measure(region_sizes, options);
  // Region id to cluster id, -1 for a region outside the size limits.
  std::vector<std::int32_t> cluster_of(region_sizes.size(), -1);
  for (std::size_t r = 0; r < region_sizes.size(); ++r) {
    if (region_sizes[r] < options.min_cluster_size || region_sizes[r] > options.max_cluster_size) {
      continue;
    }
    cluster_of[r] = static_cast<std::int32_t>(segmentation.clusters.size());
    segmentation.clusters.emplace_back();
    segmentation.clusters.back().indices.reserve(region_sizes[r]);
  }
  for (std::size_t i = 0; i < count; ++i) {
    const std::int32_t c = cluster_of[static_cast<std::size_t>(region[i])];
    if (c >= 0) {
      segmentation.clusters[static_cast<std::size_t>(c)].indices.push_back(
          static_cast<pcl::index_t>(i));
    }
  }
  progress("region growing", 1.0);
  return segmentation;
}

}  // namespace occlusion::mesh_estimation
