// The shared neighbour search and region growing of estimate_mesh against
// brute force and against the PCL classes they replace (NormalEstimation,
// KdTree's k search, RegionGrowing): same lists, same normals bit for bit,
// same clusters.

#include <gtest/gtest.h>
#include <pcl/features/normal_3d.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "mesh_estimation_stages.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "support/scenes.hpp"

namespace occlusion {
namespace {

using mesh_estimation::Cloud;
using mesh_estimation::Neighbourhoods;

// A small room with a box in it, sampled, with centimetre noise, so that
// regions of every size and curvatures above a low threshold occur.
Cloud::Ptr noisy_room(double density, double noise) {
  TriangleMesh mesh;
  testing::add_box(mesh, {0, 0, 0}, {2, 1.5, 1}, "room");
  testing::add_box(mesh, {0.6, 0.4, 0.1}, {1.1, 0.9, 0.5}, "box");
  const MeshSamples samples = sample_mesh(mesh, density, 3);
  std::mt19937 random(5);
  std::normal_distribution<double> jitter(0.0, noise);
  Cloud::Ptr cloud(new Cloud);
  for (const auto& p : samples.points) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x() + jitter(random)),
                                   static_cast<float>(p.y() + jitter(random)),
                                   static_cast<float>(p.z() + jitter(random))));
  }
  cloud->is_dense = true;
  return cloud;
}

float squared_distance(const pcl::PointXYZ& a, const pcl::PointXYZ& b) {
  return (a.getVector3fMap() - b.getVector3fMap()).squaredNorm();
}

RegionGrowingOptions small_options() {
  RegionGrowingOptions options;
  options.normal_k = 20;
  options.neighbours = 15;
  options.min_cluster_size = 30;
  options.threads = 2;
  return options;
}

TEST(MeshEstimationStages, NeighbourListsAreTheNearestNearestFirst) {
  const Cloud::Ptr cloud = noisy_room(600.0, 0.003);
  const RegionGrowingOptions options = small_options();
  const Neighbourhoods hoods = mesh_estimation::find_neighbourhoods(cloud, options, {});
  ASSERT_EQ(hoods.width, options.neighbours);
  ASSERT_EQ(hoods.neighbours.size(), cloud->size() * hoods.width);
  std::vector<float> distance(cloud->size());
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    for (std::size_t j = 0; j < cloud->size(); ++j) {
      distance[j] = squared_distance((*cloud)[i], (*cloud)[j]);
    }
    std::vector<float> sorted = distance;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(hoods.width),
                     sorted.end());
    const float first_left_out = sorted[hoods.width];
    const pcl::index_t* list = hoods.neighbours.data() + i * hoods.width;
    std::vector<pcl::index_t> unique(list, list + hoods.width);
    std::sort(unique.begin(), unique.end());
    ASSERT_EQ(std::unique(unique.begin(), unique.end()), unique.end()) << "point " << i;
    for (std::size_t n = 0; n < hoods.width; ++n) {
      const float d = distance[static_cast<std::size_t>(list[n])];
      ASSERT_LE(d, first_left_out) << "point " << i;
      if (n > 0) {
        ASSERT_LE(distance[static_cast<std::size_t>(list[n - 1])], d) << "point " << i;
      }
    }
  }
}

// `neighbours` above and below normal_k: the search takes the larger.
class SharedSearch : public ::testing::TestWithParam<std::pair<unsigned, unsigned>> {};

TEST_P(SharedSearch, ListsAndNormalsArePcls) {
  const Cloud::Ptr cloud = noisy_room(900.0, 0.002);
  RegionGrowingOptions options = small_options();
  options.normal_k = GetParam().first;
  options.neighbours = GetParam().second;
  const Neighbourhoods hoods = mesh_estimation::find_neighbourhoods(cloud, options, {});

  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>(false));
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(cloud);
  estimation.setSearchMethod(tree);
  estimation.setKSearch(static_cast<int>(options.normal_k));
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  ASSERT_EQ(normals.size(), cloud->size());

  pcl::Indices found;
  std::vector<float> distances;
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    // Bit for bit: the same neighbours in the same order give the same sums.
    const Eigen::Vector3f normal = normals[i].getNormalVector3fMap();
    ASSERT_EQ(std::memcmp(normal.data(), hoods.normals[i].data(), sizeof(float) * 3), 0)
        << "point " << i;
    ASSERT_EQ(std::memcmp(&normals[i].curvature, &hoods.curvatures[i], sizeof(float)), 0)
        << "point " << i;

    tree->nearestKSearch(static_cast<int>(i), static_cast<int>(options.neighbours), found,
                         distances);
    std::vector<pcl::index_t> ours(
        hoods.neighbours.begin() + static_cast<std::ptrdiff_t>(i * hoods.width),
        hoods.neighbours.begin() + static_cast<std::ptrdiff_t>((i + 1) * hoods.width));
    std::sort(found.begin(), found.end());
    std::sort(ours.begin(), ours.end());
    ASSERT_EQ(ours, found) << "point " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(MeshEstimationStages, SharedSearch,
                         ::testing::Values(std::make_pair(20u, 15u), std::make_pair(10u, 25u),
                                           std::make_pair(12u, 12u)));

// PCL's region growing with the region sizes it drops.
class PclRegionGrowing : public pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> {
 public:
  std::vector<pcl::uindex_t> region_sizes() const { return num_pts_in_segment_; }
};

struct GrowingCase {
  double smoothness_degrees;
  double curvature_threshold;
  std::size_t min_cluster_size, max_cluster_size;
};

class SameRegions : public ::testing::TestWithParam<GrowingCase> {};

TEST_P(SameRegions, AsPclRegionGrowing) {
  const Cloud::Ptr cloud = noisy_room(900.0, 0.004);
  RegionGrowingOptions options = small_options();
  options.smoothness_degrees = GetParam().smoothness_degrees;
  options.curvature_threshold = GetParam().curvature_threshold;
  options.min_cluster_size = GetParam().min_cluster_size;
  options.max_cluster_size = GetParam().max_cluster_size;
  const Neighbourhoods hoods = mesh_estimation::find_neighbourhoods(cloud, options, {});
  const mesh_estimation::Segmentation ours = mesh_estimation::grow_regions(hoods, options, {});

  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>(false));
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(cloud);
  estimation.setSearchMethod(tree);
  estimation.setKSearch(static_cast<int>(options.normal_k));
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  estimation.compute(*normals);
  PclRegionGrowing growing;
  growing.setMinClusterSize(static_cast<pcl::uindex_t>(options.min_cluster_size));
  growing.setMaxClusterSize(static_cast<pcl::uindex_t>(options.max_cluster_size));
  growing.setSearchMethod(tree);
  growing.setNumberOfNeighbours(options.neighbours);
  growing.setInputCloud(cloud);
  growing.setInputNormals(normals);
  growing.setSmoothnessThreshold(
      static_cast<float>(options.smoothness_degrees * 3.14159265358979323846 / 180.0));
  growing.setCurvatureThreshold(static_cast<float>(options.curvature_threshold));
  std::vector<pcl::PointIndices> theirs;
  growing.extract(theirs);

  const std::vector<pcl::uindex_t> sizes = growing.region_sizes();
  EXPECT_EQ(ours.regions.regions, sizes.size());
  EXPECT_EQ(ours.regions.largest, *std::max_element(sizes.begin(), sizes.end()));
  std::size_t too_small = 0;
  for (const pcl::uindex_t size : sizes) too_small += size < options.min_cluster_size ? 1 : 0;
  EXPECT_EQ(ours.regions.too_small, too_small);
  EXPECT_GT(too_small, 0u);  // the case does drop regions
  ASSERT_EQ(ours.clusters.size(), theirs.size());
  EXPECT_GT(theirs.size(), 1u);
  for (std::size_t c = 0; c < theirs.size(); ++c) {
    EXPECT_EQ(ours.clusters[c].indices, theirs[c].indices) << "cluster " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(MeshEstimationStages, SameRegions,
                         ::testing::Values(GrowingCase{4.0, 1.0, 30, 100000},
                                           GrowingCase{8.0, 0.02, 30, 100000},
                                           GrowingCase{3.0, 0.05, 5, 2000}));

}  // namespace
}  // namespace occlusion
