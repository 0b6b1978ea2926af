// Normals and region growing with PCL, as the seed does (listings 4.6, 4.7),
// with two changes PCL allows through its virtual hooks: the neighbour search
// runs on every core in blocks (progress, cancel), and the sizes of the regions
// PCL drops are kept, so that an empty result can say which limit removed what.

#include <pcl/features/normal_3d_omp.h>
#include <pcl/segmentation/region_growing.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh_estimation_stages.hpp"
#include "occlusion/core/parallel.hpp"

namespace occlusion::mesh_estimation {

namespace {

// About 20 progress steps, but no block so small that the threads idle.
std::size_t block_size(std::size_t count) {
  return std::max<std::size_t>(count / 20, 4096);
}

class SizedRegionGrowing : public pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> {
 public:
  SizedRegionGrowing(unsigned threads, const Progress& progress)
      : threads_(threads), progress_(progress) {}

  // Valid after extract(): every region grown, measured against the limits.
  RegionSizes sizes() const {
    RegionSizes sizes;
    for (const pcl::uindex_t points : num_pts_in_segment_) {
      ++sizes.regions;
      sizes.largest = std::max<std::size_t>(sizes.largest, points);
      if (points < min_pts_per_cluster_) {
        ++sizes.too_small;
        sizes.too_small_points += points;
      } else if (points > max_pts_per_cluster_) {
        ++sizes.too_large;
        sizes.too_large_points += points;
      }
    }
    return sizes;
  }

 protected:
  // The base class's checks, minus rebuilding the kd-tree the normals already built.
  bool prepareForSegmentation() override {
    if (input_->points.empty() || !normals_ || input_->size() != normals_->size() ||
        neighbour_number_ == 0) {
      return false;
    }
    if (!search_) search_.reset(new Tree);
    if (search_->getInputCloud() != input_) search_->setInputCloud(input_);
    return true;
  }

  void findPointNeighbours() override {
    const std::size_t count = input_->size();
    point_neighbours_.assign(count, pcl::Indices());
    const int k = static_cast<int>(neighbour_number_);
    const std::size_t block = block_size(count);
    for (std::size_t begin = 0; begin < count; begin += block) {
      const std::size_t end = std::min(count, begin + block);
      parallel_for(end - begin, 1024, threads_, [&](std::size_t first, std::size_t last) {
        std::vector<float> distances;
        for (std::size_t i = begin + first; i < begin + last; ++i) {
          search_->nearestKSearch((*input_)[i], k, point_neighbours_[i], distances);
        }
      });
      progress_.check_cancel();
      progress_("region growing", 0.8 * static_cast<double>(end) / static_cast<double>(count));
    }
  }

 private:
  unsigned threads_;
  const Progress& progress_;
};

}  // namespace

Normals::Ptr estimate_normals(const Cloud::ConstPtr& cloud, const Tree::Ptr& tree,
                              const RegionGrowingOptions& options, const Progress& progress) {
  // The OpenMP runtime ends the whole process when it cannot start a thread
  // ("threads": 40000 did), and threads beyond the cores buy nothing here.
  const unsigned threads = std::min(resolve_thread_count(options.threads), resolve_thread_count(0));
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation(threads);
  estimation.setInputCloud(cloud);
  estimation.setSearchMethod(tree);
  // PCL takes k as an int; beyond the cloud's size the search gives every point anyway.
  estimation.setKSearch(static_cast<int>(std::min<std::size_t>(options.normal_k, cloud->size())));

  const std::size_t count = cloud->size();
  Normals::Ptr normals(new Normals);
  normals->resize(count);
  const std::size_t block = block_size(count);
  Normals part;
  progress("normals", 0.0);
  for (std::size_t begin = 0; begin < count; begin += block) {
    const std::size_t end = std::min(count, begin + block);
    pcl::IndicesPtr indices(new pcl::Indices(end - begin));
    for (std::size_t i = begin; i < end; ++i) (*indices)[i - begin] = static_cast<pcl::index_t>(i);
    // The whole cloud stays the search surface; only the points to compute change.
    estimation.setIndices(indices);
    estimation.compute(part);
    std::copy(part.begin(), part.end(), normals->begin() + static_cast<std::ptrdiff_t>(begin));
    progress.check_cancel();
    progress("normals", static_cast<double>(end) / static_cast<double>(count));
  }
  return normals;
}

Segmentation grow_regions(const Cloud::ConstPtr& cloud, const Normals::Ptr& normals,
                          const Tree::Ptr& tree, const RegionGrowingOptions& options,
                          const Progress& progress) {
  constexpr double kDegrees = 3.14159265358979323846 / 180.0;
  constexpr std::size_t kMaxSize = std::numeric_limits<pcl::uindex_t>::max();
  SizedRegionGrowing growing(options.threads, progress);
  growing.setMinClusterSize(
      static_cast<pcl::uindex_t>(std::min(options.min_cluster_size, kMaxSize)));
  growing.setMaxClusterSize(
      static_cast<pcl::uindex_t>(std::min(options.max_cluster_size, kMaxSize)));
  growing.setSearchMethod(tree);
  growing.setNumberOfNeighbours(options.neighbours);
  growing.setInputCloud(cloud);
  growing.setInputNormals(normals);
  growing.setSmoothnessThreshold(static_cast<float>(options.smoothness_degrees * kDegrees));
  growing.setCurvatureThreshold(static_cast<float>(options.curvature_threshold));

  progress("region growing", 0.0);
  Segmentation segmentation;
  growing.extract(segmentation.clusters);
  segmentation.regions = growing.sizes();
  progress("region growing", 1.0);
  return segmentation;
}

}  // namespace occlusion::mesh_estimation
