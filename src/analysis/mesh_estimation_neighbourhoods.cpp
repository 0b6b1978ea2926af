// One k-nearest-neighbour search per point serves both normals and region
// growing (and later edge recovery): the kd-tree PCL's KdTreeFLANN builds
// (FLANN's single kd-tree, leaves of 15, same floats) is built once, each
// point's max(normal_k, neighbours) nearest are found once, the normal is
// computed from them exactly as NormalEstimationOMP does (same search, same
// order, same pcl::computePointNormal, same flip), and the `neighbours` nearest
// are kept in NeighbourLists. FLANN returns them nearest first, so they are the
// set PCL's region growing would get from its own k = neighbours search
// (points at exactly the same distance as the last one kept aside). The tree is
// freed on return.
//
// FLANN is called directly, as KdTreeFLANN::nearestKSearch would call it, with
// the same result set; what that wrapper adds per query (an OpenMP region in
// FLANN's knnSearch, a copy of the query, index conversions) cost more than
// the search, and its float copy of the cloud 12 bytes per point.

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>
#include <pcl/features/normal_3d.h>

#include <algorithm>
#include <limits>
#include <mutex>
#include <utility>

#include "mesh_estimation_stages.hpp"
#include "occlusion/core/parallel.hpp"

namespace occlusion::mesh_estimation {

namespace {

using FlannTree = flann::KDTreeSingleIndex<flann::L2_Simple<float>>;
// KdTreeFLANN's: leaves of 15 points; exact search (eps 0). Not reordered: the
// search reads the same floats in the same order from the cloud itself
// instead of a 12-byte-per-point copy in tree order, and finds the same.
constexpr int kLeafSize = 15;
constexpr bool kReorder = false;

// About 20 progress steps, but no block so small that the threads idle.
std::size_t block_size(std::size_t count) {
  return std::max<std::size_t>(count / 20, 4096);
}

// NormalEstimation's normal from the `normal_k` nearest (nearest first), as
// its computeFeature writes it: NaN when PCL finds none, else flipped towards
// the cloud's sensor origin (0, 0, 0 here).
void store_normal(const Cloud& cloud, std::size_t i, const pcl::Indices& nearest,
                  Neighbourhoods& hoods) {
  Eigen::Vector4f plane;
  float curvature = 0.0f;
  if (nearest.empty() || !pcl::computePointNormal(cloud, nearest, plane, curvature)) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    hoods.normals[i] = Eigen::Vector3f::Constant(nan);
    hoods.curvatures[i] = nan;
    return;
  }
  pcl::flipNormalTowardsViewpoint(cloud[i], 0.0f, 0.0f, 0.0f, plane[0], plane[1], plane[2]);
  hoods.normals[i] = plane.head<3>();
  hoods.curvatures[i] = curvature;
}

}  // namespace

Neighbourhoods find_neighbourhoods(const Cloud::ConstPtr& cloud,
                                   const RegionGrowingOptions& options, const Progress& progress) {
  const std::size_t count = cloud->size();
  // PCL takes k as an int; beyond the cloud's size the search gives every point anyway.
  const std::size_t normal_k = std::min<std::size_t>(options.normal_k, count);
  const std::size_t width = std::min<std::size_t>(options.neighbours, count);
  const std::size_t k = std::max(normal_k, width);

  Neighbourhoods hoods;
  hoods.lists = NeighbourLists(&(*cloud)[0].x, sizeof(pcl::PointXYZ), count, width);
  hoods.normals.resize(count);
  hoods.curvatures.resize(count);

  // The points in place: x, y, z at the start of every 16-byte PointXYZ.
  const flann::Matrix<float> points(const_cast<float*>(&(*cloud)[0].x), count, 3,
                                    sizeof(pcl::PointXYZ));
  FlannTree tree(points, flann::KDTreeSingleIndexParams(kLeafSize, kReorder));
  tree.buildIndex();
  const flann::SearchParams search(/*checks=*/-1, /*eps=*/0.0f, /*sorted=*/false);
  const std::size_t block = block_size(count);
  progress("normals", 0.0);
  for (std::size_t begin = 0; begin < count; begin += block) {
    const std::size_t end = std::min(count, begin + block);
    // Lists NeighbourLists keeps whole, stored in point order after the block.
    std::vector<std::pair<std::size_t, pcl::Indices>> whole;
    std::mutex whole_mutex;
    parallel_for(end - begin, 1024, options.threads, [&](std::size_t first, std::size_t last) {
      flann::KNNSimpleResultSet<float> found(k);
      std::vector<std::size_t> ids(k);
      std::vector<float> distances(k);
      pcl::Indices nearest, normal_nearest;
      for (std::size_t i = begin + first; i < begin + last; ++i) {
        // As FLANN's knnSearch does per query; nearest first.
        found.clear();
        tree.findNeighbors(found, &(*cloud)[i].x, search);
        const std::size_t n = std::min(found.size(), k);
        found.copy(ids.data(), distances.data(), n, search.sorted);
        nearest.resize(n);
        for (std::size_t j = 0; j < n; ++j) nearest[j] = static_cast<pcl::index_t>(ids[j]);
        if (nearest.size() == normal_k) {
          store_normal(*cloud, i, nearest, hoods);
        } else {
          normal_nearest.assign(
              nearest.begin(),
              nearest.begin() + static_cast<std::ptrdiff_t>(std::min(normal_k, nearest.size())));
          store_normal(*cloud, i, normal_nearest, hoods);
        }
        // FLANN always fills k >= width; pad with the point itself (in its own
        // region already, in no cluster as an edge point) were it ever short.
        nearest.resize(std::max(nearest.size(), width), static_cast<pcl::index_t>(i));
        if (!hoods.lists.try_set(i, nearest.data())) {
          nearest.resize(width);
          const std::lock_guard<std::mutex> lock(whole_mutex);
          whole.emplace_back(i, nearest);
        }
      }
    });
    std::sort(whole.begin(), whole.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [i, list] : whole) hoods.lists.set_whole(i, list.data());
    progress.check_cancel();
    progress("normals", static_cast<double>(end) / static_cast<double>(count));
  }
  return hoods;
}

}  // namespace occlusion::mesh_estimation
