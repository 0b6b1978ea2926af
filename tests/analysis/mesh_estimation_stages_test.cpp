// The shared neighbour search and region growing of estimate_mesh against
// brute force and against the PCL classes they replace (NormalEstimation,
// KdTree's k search, RegionGrowing): same lists, same normals bit for bit,
// same clusters.

#include <gtest/gtest.h>
#include <pcl/features/normal_3d.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <utility>

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

std::vector<pcl::index_t> list_of(const Neighbourhoods& hoods, std::size_t point) {
  std::vector<pcl::index_t> list;
  hoods.lists.for_each(point, [&list](std::int32_t n) { list.push_back(n); });
  return list;
}

// Lists come back as stored, in order, those with far neighbours (kept whole) too.
TEST(NeighbourLists, GiveBackWhatWasStored) {
  constexpr std::size_t kCount = 100000, kWidth = 7;
  std::vector<Eigen::Vector3f> positions(kCount);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> coordinate(-5.0f, 5.0f);
  for (auto& p : positions)
    p = Eigen::Vector3f(coordinate(random), coordinate(random), coordinate(random));
  mesh_estimation::NeighbourLists lists(positions[0].data(), sizeof(Eigen::Vector3f), kCount,
                                        kWidth);
  std::vector<std::int32_t> stored(kCount * kWidth);
  std::uniform_int_distribution<std::int32_t> any(0, kCount - 1), near(-3, 3);
  std::vector<std::size_t> refused;
  for (std::size_t i = 0; i < kCount; ++i) {
    std::int32_t* list = stored.data() + i * kWidth;
    for (std::size_t n = 0; n < kWidth; ++n) {
      // Mostly points next in index order (random in space), now and then any point.
      list[n] = n == 3 && i % 2 == 0
                    ? any(random)
                    : std::clamp<std::int32_t>(static_cast<std::int32_t>(i) + near(random), 0,
                                               kCount - 1);
    }
    if (!lists.try_set(i, list)) refused.push_back(i);
  }
  for (const std::size_t i : refused) lists.set_whole(i, stored.data() + i * kWidth);
  EXPECT_EQ(lists.whole_lists(), refused.size());
  EXPECT_GT(refused.size(), 0u);
  EXPECT_LT(refused.size(), kCount);
  for (std::size_t i = 0; i < kCount; ++i) {
    std::vector<std::int32_t> back;
    lists.for_each(i, [&back](std::int32_t n) { back.push_back(n); });
    ASSERT_EQ(back, std::vector<std::int32_t>(
                        stored.begin() + static_cast<std::ptrdiff_t>(i * kWidth),
                        stored.begin() + static_cast<std::ptrdiff_t>((i + 1) * kWidth)))
        << "point " << i;
  }
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
  const std::size_t width = hoods.lists.width();
  ASSERT_EQ(width, options.neighbours);
  ASSERT_EQ(hoods.lists.size(), cloud->size());
  std::vector<float> distance(cloud->size());
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    for (std::size_t j = 0; j < cloud->size(); ++j) {
      distance[j] = squared_distance((*cloud)[i], (*cloud)[j]);
    }
    std::vector<float> sorted = distance;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(width),
                     sorted.end());
    const float first_left_out = sorted[width];
    const std::vector<pcl::index_t> list = list_of(hoods, i);
    ASSERT_EQ(list.size(), width);
    std::vector<pcl::index_t> unique = list;
    std::sort(unique.begin(), unique.end());
    ASSERT_EQ(std::unique(unique.begin(), unique.end()), unique.end()) << "point " << i;
    for (std::size_t n = 0; n < width; ++n) {
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
    std::vector<pcl::index_t> ours = list_of(hoods, i);
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

// Edge recovery from the candidates (each unclustered point's distinct
// neighbour clusters, taken before the lists are freed) against its
// definition over the whole lists: walk the point's neighbours nearest first
// and join up to three clusters whose plane is within ransac_distance.
TEST(MeshEstimationStages, EdgeRecoveryFromCandidatesIsFromTheWholeLists) {
  const Cloud::Ptr cloud = noisy_room(600.0, 0.01);
  RegionGrowingOptions options = small_options();
  options.curvature_threshold = 0.05;
  const Neighbourhoods hoods = mesh_estimation::find_neighbourhoods(cloud, options, {});
  const mesh_estimation::Segmentation segmentation =
      mesh_estimation::grow_regions(hoods, options, {});
  std::vector<std::int32_t> label(cloud->size(), -1);
  for (std::size_t c = 0; c < segmentation.clusters.size(); ++c) {
    for (const pcl::index_t i : segmentation.clusters[c].indices) {
      label[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(c);
    }
  }
  std::vector<mesh_estimation::PlaneOutcome> planes;
  for (const auto& cluster : segmentation.clusters) {
    planes.push_back(mesh_estimation::fit_plane(cloud, cluster, options));
  }

  // The definition, over the whole lists.
  std::vector<std::array<std::int32_t, 3>> expected(cloud->size(), {-1, -1, -1});
  std::size_t expected_edges = 0;
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    if (label[i] >= 0) continue;
    const Eigen::Vector3d p = (*cloud)[i].getVector3fMap().cast<double>();
    std::size_t count = 0;
    for (const pcl::index_t n : list_of(hoods, i)) {
      const std::int32_t c = label[static_cast<std::size_t>(n)];
      if (c < 0 || count == 3) continue;
      if (std::find(expected[i].begin(), expected[i].begin() + count, c) !=
          expected[i].begin() + count) {
        continue;
      }
      const auto& plane = planes[static_cast<std::size_t>(c)].plane;
      if (!plane || std::abs(plane->normal.dot(p) + plane->offset) > options.ransac_distance) {
        continue;
      }
      expected[i][count++] = c;
    }
    expected_edges += count > 0 ? 1 : 0;
  }
  ASSERT_GT(expected_edges, 0u);  // the case does recover edge points

  mesh_estimation::EdgeCandidates candidates = mesh_estimation::edge_candidates(hoods, label);
  const mesh_estimation::EdgePoints edges =
      mesh_estimation::recover_edge_points(cloud, std::move(candidates), planes, options);
  std::vector<std::array<std::int32_t, 3>> got(cloud->size(), {-1, -1, -1});
  ASSERT_EQ(edges.points.size(), edges.planes.size());
  for (std::size_t e = 0; e < edges.points.size(); ++e) {
    const auto i = static_cast<std::size_t>(edges.points[e]);
    ASSERT_LT(label[i], 0) << "point " << i << " is in a cluster";
    got[i] = edges.planes[e];
  }
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    ASSERT_EQ(got[i], expected[i]) << "point " << i;
  }
}

}  // namespace
}  // namespace occlusion
