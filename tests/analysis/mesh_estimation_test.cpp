#include "occlusion/analysis/mesh_estimation.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>

#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "support/scenes.hpp"

namespace occlusion {
namespace {

using testing::add_box;
using testing::add_quad;

// 2,500 random points per square metre: 2 cm apart, as a tidy indoor scan.
constexpr double kDensity = 2500.0;

PointCloud sample_cloud(const TriangleMesh& mesh, double density, std::uint64_t seed = 7) {
  const MeshSamples samples = sample_mesh(mesh, density, seed);
  PointCloud cloud;
  cloud.positions.reserve(samples.size());
  for (const auto& p : samples.points) cloud.positions.push_back(p.cast<float>());
  return cloud;
}

// The room [0,4] x [0,3.5] x [0,2.5] with a wardrobe 0.3 m from the wall x = 4,
// floating 0.2 m above the floor so that no two faces touch: from the pattern-7
// viewpoints it hides most of the wall and floor behind it and its own back.
TriangleMesh room_with_wardrobe() {
  TriangleMesh mesh;
  add_box(mesh, {0, 0, 0}, {4, 3.5, 2.5}, "room");
  add_box(mesh, {3.2, 0.5, 0.2}, {3.7, 3.0, 2.0}, "wardrobe");
  return mesh;
}

// The plane whose normal is along `axis` and that passes through `at` along it.
const EstimatedPlane* plane_at(const MeshEstimate& estimate, int axis, double at) {
  const EstimatedPlane* found = nullptr;
  for (const auto& plane : estimate.planes) {
    if (std::abs(plane.normal[axis]) < 0.999) continue;
    // normal . p + offset = 0 with p[axis] = at.
    if (std::abs(plane.normal[axis] * at + plane.offset) > 0.01) continue;
    if (found == nullptr || plane.area > found->area) found = &plane;
  }
  return found;
}

RegionGrowingOptions room_options() {
  RegionGrowingOptions options;
  options.max_cluster_size = 1000000;  // the seed's 100,000 would drop the floor
  return options;
}

TEST(MeshEstimation, BoxRoomGivesSixPlanesWithTheirAreas) {
  TriangleMesh room;
  add_box(room, {0, 0, 0}, {4, 3.5, 2.5}, "room");
  const PointCloud cloud = sample_cloud(room, kDensity);
  const MeshEstimate estimate = estimate_mesh(cloud, room_options());

  EXPECT_EQ(estimate.clusters_used, 6u) << estimate.clusters_found << " found";
  const Eigen::Vector3d size(4, 3.5, 2.5);
  for (int axis = 0; axis < 3; ++axis) {
    const double truth = size[(axis + 1) % 3] * size[(axis + 2) % 3];
    for (const double at : {0.0, size[axis]}) {
      const EstimatedPlane* plane = plane_at(estimate, axis, at);
      ASSERT_NE(plane, nullptr) << "no plane " << axis << " = " << at;
      EXPECT_NEAR(plane->area, truth, 0.02 * truth) << "plane " << axis << " = " << at;
      EXPECT_NEAR(plane->centroid[axis], at, 0.01);
    }
  }
  EXPECT_GT(estimate.covered_fraction, 0.9);
  EXPECT_TRUE(estimate.skipped.empty());
  EXPECT_EQ(estimate.non_finite_points, 0u);
  // Every face of the mesh belongs to a used cluster.
  ASSERT_EQ(estimate.mesh.face_group.size(), estimate.mesh.face_count());
  estimate.mesh.validate();
  EXPECT_EQ(estimate.mesh.group_names.size(), estimate.clusters_found);
}

TEST(MeshEstimation, WithoutEdgeRecoveryPolygonsFallShortOfTheEdges) {
  // The seed's method as is: the strip along each edge, whose normals lean
  // towards the neighbouring face, is in no cluster; 3 cm spacing here.
  TriangleMesh room;
  add_box(room, {0, 0, 0}, {4, 3.5, 2.5}, "room");
  const PointCloud cloud = sample_cloud(room, 1100.0);
  RegionGrowingOptions options = room_options();
  options.recover_edges = false;
  const MeshEstimate seed = estimate_mesh(cloud, options);
  EXPECT_EQ(seed.edge_points, 0u);
  const EstimatedPlane* floor = plane_at(seed, 2, 0.0);
  ASSERT_NE(floor, nullptr);
  EXPECT_LT(floor->area, 0.98 * 14.0);
  EXPECT_LT(seed.covered_fraction, 0.97);

  const MeshEstimate recovered = estimate_mesh(cloud, room_options());
  EXPECT_GT(recovered.edge_points, 0u);
  EXPECT_NEAR(plane_at(recovered, 2, 0.0)->area, 14.0, 0.02 * 14.0);
  EXPECT_GT(recovered.covered_fraction, 0.99);
  // Recovery moves no point between clusters.
  EXPECT_EQ(recovered.point_cluster, seed.point_cluster);
}

TEST(MeshEstimation, EstimatedMeshOccludesLikeTheExactOne) {
  const TriangleMesh exact = room_with_wardrobe();
  const PointCloud cloud = sample_cloud(exact, kDensity);
  const MeshEstimate estimate = estimate_mesh(cloud, room_options());
  EXPECT_EQ(estimate.clusters_used, 12u);

  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  const auto viewpoints = pattern_viewpoints(7, lo.cast<double>(), hi.cast<double>());
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 400;
  const MeshOcclusionResult truth = compute_mesh_occlusion(exact, viewpoints, options);
  const MeshOcclusionResult estimated = compute_mesh_occlusion(estimate.mesh, viewpoints, options);
  EXPECT_GT(truth.occlusion_level, 0.15);  // the wardrobe really hides something
  EXPECT_NEAR(estimated.occlusion_level, truth.occlusion_level, 0.02);
  EXPECT_NEAR(estimated.total_area, truth.total_area, 0.02 * truth.total_area);
}

TEST(MeshEstimation, TableTopIsItsOwnCluster) {
  TriangleMesh room;
  add_box(room, {0, 0, 0}, {4, 3.5, 2.5}, "room");
  const double top = 0.75;
  add_quad(room, {1.0, 1.0, top}, {1.6, 0, 0}, {0, 0.9, 0}, "table top");
  for (const double x : {1.05, 2.5}) {
    for (const double y : {1.05, 1.8}) {
      add_box(room, {x, y, 0}, {x + 0.05, y + 0.05, top}, "leg");
    }
  }
  const PointCloud cloud = sample_cloud(room, kDensity);
  const MeshEstimate estimate = estimate_mesh(cloud, room_options());

  const EstimatedPlane* table = plane_at(estimate, 2, top);
  ASSERT_NE(table, nullptr);
  EXPECT_NEAR(table->area, 1.6 * 0.9, 0.05 * 1.6 * 0.9);
  const EstimatedPlane* floor = plane_at(estimate, 2, 0.0);
  ASSERT_NE(floor, nullptr);
  EXPECT_NE(table->cluster, floor->cluster);
  // The table top's cluster holds no floor point, the floor's no table-top
  // point. (Points on the legs just under the top may join the top: their
  // normals lean towards its.)
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::int32_t cluster = estimate.point_cluster[i];
    const float z = cloud.positions[i].z();
    if (cluster == static_cast<std::int32_t>(table->cluster)) {
      EXPECT_NEAR(z, top, 0.02) << "point " << i;
    }
    if (cluster == static_cast<std::int32_t>(floor->cluster)) {
      EXPECT_LT(z, 0.02) << "point " << i;
    }
  }
}

TEST(MeshEstimation, WallScannedRowByRowKeepsItsHull) {
  // The points of a 21 x 21 grid on the wall x = 1, row by row: the first,
  // middle and last lie on the diagonal, and PCL's 2-D hull, handed these 3-D
  // points as they come, projects the wall onto the xy plane, a line (QH6013).
  PointCloud wall;
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 20; ++j) {
      wall.positions.emplace_back(1.0f, 0.05f * static_cast<float>(i),
                                  0.05f * static_cast<float>(j));
    }
  }
  const MeshEstimate estimate = estimate_mesh(wall, {});
  ASSERT_EQ(estimate.clusters_used, 1u);
  EXPECT_NEAR(estimate.planes[0].area, 1.0, 1e-5);
  EXPECT_NEAR(std::abs(estimate.planes[0].normal.x()), 1.0, 1e-6);
}

PointCloud line_of_points(std::size_t count) {
  PointCloud cloud;
  for (std::size_t i = 0; i < count; ++i) {
    const float t = 0.01f * static_cast<float>(i);
    cloud.positions.emplace_back(1.0f + t, 2.0f + 0.5f * t, 0.3f + 0.25f * t);
  }
  return cloud;
}

TEST(MeshEstimation, LineOfPointsIsNoPlaneAndSaysWhy) {
  try {
    estimate_mesh(line_of_points(2000), {});
    FAIL() << "a line gave a plane";
  } catch (const NoPlaneFound& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("collinear"), std::string::npos) << message;
    EXPECT_NE(message.find("lines"), std::string::npos) << message;
  }
}

PointCloud small_square(std::size_t side) {
  PointCloud cloud;
  for (std::size_t i = 0; i < side; ++i) {
    for (std::size_t j = 0; j < side; ++j) {
      cloud.positions.emplace_back(0.1f * static_cast<float>(i), 0.1f * static_cast<float>(j),
                                   1.0f);
    }
  }
  return cloud;
}

TEST(MeshEstimation, TenPointsNeedASmallerMinimumClusterSize) {
  PointCloud ten = small_square(3);
  ten.positions.emplace_back(0.15f, 0.05f, 1.0f);
  ASSERT_EQ(ten.size(), 10u);
  try {
    estimate_mesh(ten, {});
    FAIL() << "10 points made a cluster of at least 100";
  } catch (const NoPlaneFound& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("lower min_cluster_size to 10"), std::string::npos) << message;
  }
  // Following the hint works.
  RegionGrowingOptions options;
  options.min_cluster_size = 10;
  const MeshEstimate estimate = estimate_mesh(ten, options);
  ASSERT_EQ(estimate.clusters_used, 1u);
  EXPECT_NEAR(estimate.planes[0].area, 0.04, 1e-6);
  EXPECT_EQ(estimate.covered_fraction, 1.0);
}

TEST(MeshEstimation, NonFinitePointsAreLeftOutAndCounted) {
  PointCloud cloud = small_square(20);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.positions[5] = Eigen::Vector3f(nan, 0, 0);
  cloud.positions.emplace_back(nan, nan, nan);
  cloud.positions.emplace_back(std::numeric_limits<float>::infinity(), 0, 0);
  const MeshEstimate estimate = estimate_mesh(cloud, {});
  EXPECT_EQ(estimate.non_finite_points, 3u);
  ASSERT_EQ(estimate.point_cluster.size(), cloud.size());
  EXPECT_EQ(estimate.point_cluster[5], -1);
  EXPECT_EQ(estimate.point_cluster.back(), -1);
  EXPECT_EQ(estimate.clusters_used, 1u);
  EXPECT_EQ(estimate.covered_points, 400u - 1u);
  EXPECT_NEAR(estimate.planes[0].area, 1.9 * 1.9, 1e-5);

  PointCloud all_nan;
  all_nan.positions.assign(5, Eigen::Vector3f(nan, nan, nan));
  EXPECT_THROW(estimate_mesh(all_nan, {}), std::invalid_argument);
  EXPECT_THROW(estimate_mesh(PointCloud{}, {}), std::invalid_argument);
}

TEST(MeshEstimation, OversizedRegionsAreNamedInTheHint) {
  RegionGrowingOptions options;
  options.max_cluster_size = 200;
  try {
    estimate_mesh(small_square(20), options);
    FAIL() << "a 400-point plane fit under max_cluster_size 200";
  } catch (const NoPlaneFound& e) {
    EXPECT_NE(std::string(e.what()).find("raise max_cluster_size"), std::string::npos) << e.what();
  }
}

TEST(MeshEstimation, DegenerateClustersAreSkippedNotFatal) {
  // A plane and, far away, a line dense enough to be its own region.
  PointCloud cloud = small_square(20);
  const PointCloud line = line_of_points(400);
  for (const auto& p : line.positions) cloud.positions.push_back(p + Eigen::Vector3f(20, 0, 0));
  const MeshEstimate estimate = estimate_mesh(cloud, {});
  EXPECT_EQ(estimate.clusters_used, 1u);
  ASSERT_FALSE(estimate.skipped.empty());
  for (const auto& skipped : estimate.skipped) {
    EXPECT_EQ(skipped.reason, SkipReason::kCollinear) << skipped.detail;
    EXPECT_GE(skipped.points, 100u);
  }
  EXPECT_EQ(estimate.clusters_found, estimate.clusters_used + estimate.skipped.size());
}

TEST(MeshEstimation, InvalidOptionsAreRejected) {
  const PointCloud cloud = small_square(20);
  const auto with = [](auto change) {
    RegionGrowingOptions options;
    change(options);
    return options;
  };
  EXPECT_THROW(estimate_mesh(cloud, with([](auto& o) { o.normal_k = 2; })), std::invalid_argument);
  EXPECT_THROW(estimate_mesh(cloud, with([](auto& o) { o.neighbours = 0; })),
               std::invalid_argument);
  EXPECT_THROW(estimate_mesh(cloud, with([](auto& o) { o.max_cluster_size = 10; })),
               std::invalid_argument);
  EXPECT_THROW(estimate_mesh(cloud, with([](auto& o) { o.smoothness_degrees = 0; })),
               std::invalid_argument);
  EXPECT_THROW(estimate_mesh(cloud, with([](auto& o) { o.ransac_distance = -1; })),
               std::invalid_argument);
  EXPECT_THROW(estimate_mesh(cloud, with([](auto& o) { o.curvature_threshold = NAN; })),
               std::invalid_argument);
}

TEST(MeshEstimation, ThreadsDoNotChangeTheMesh) {
  const PointCloud cloud = sample_cloud(room_with_wardrobe(), 900.0);
  RegionGrowingOptions options = room_options();
  options.threads = 1;
  const MeshEstimate one = estimate_mesh(cloud, options);
  options.threads = 3;
  const MeshEstimate three = estimate_mesh(cloud, options);
  EXPECT_EQ(one.mesh.vertices, three.mesh.vertices);
  EXPECT_EQ(one.mesh.faces, three.mesh.faces);
  EXPECT_EQ(one.point_cluster, three.point_cluster);
}

TEST(MeshEstimation, ReportsStagesAndCancels) {
  const PointCloud cloud = small_square(20);
  std::vector<std::string> stages;
  Progress progress;
  progress.report = [&stages](const std::string& stage, double) {
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
  };
  estimate_mesh(cloud, {}, progress);
  EXPECT_EQ(stages, (std::vector<std::string>{"normals", "region growing", "planes", "hulls"}));

  std::atomic<bool> cancel{true};
  progress.cancel = &cancel;
  EXPECT_THROW(estimate_mesh(cloud, {}, progress), Cancelled);
}

}  // namespace
}  // namespace occlusion
