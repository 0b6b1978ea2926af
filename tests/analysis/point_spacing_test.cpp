#include "occlusion/analysis/point_spacing.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "occlusion/analysis/scan.hpp"
#include "support/cloud_scenes.hpp"
#include "support/kinect_frame.hpp"

namespace occlusion {
namespace {

using testing::add_grid;

PointCloud plane_grid(int n, double step) {
  PointCloud cloud;
  add_grid(cloud, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), n, n,
           step);
  return cloud;
}

TEST(PointSpacing, SquareGridSpacingIsItsStep) {
  const PointSpacing spacing = measure_point_spacing(plane_grid(100, 0.05));
  EXPECT_NEAR(spacing.spacing, 0.05, 1e-6);
  EXPECT_NEAR(spacing.quantile_10, 0.05, 1e-6);
  EXPECT_NEAR(spacing.quantile_90, 0.05, 1e-6);
  EXPECT_EQ(spacing.duplicate_hits, 0u);
  EXPECT_GT(spacing.samples, 5000u);
}

TEST(PointSpacing, EveryPointStoredTwiceKeepsTheSpacing) {
  PointCloud cloud = plane_grid(100, 0.05);
  const std::vector<Eigen::Vector3f> once = cloud.positions;
  cloud.positions.insert(cloud.positions.end(), once.begin(), once.end());
  const PointSpacing spacing = measure_point_spacing(cloud);
  EXPECT_NEAR(spacing.spacing, 0.05, 1e-6);
  EXPECT_EQ(spacing.duplicate_hits, spacing.samples);
}

TEST(PointSpacing, MedianIgnoresFarStraysAndSparseTails) {
  // 70 % of the points at 1 cm, 30 % at 4 cm (farther from the scanner), and a
  // few strays metres away: the median is the dense surface's spacing.
  PointCloud cloud = plane_grid(100, 0.01);
  add_grid(cloud, {0, 0, 5}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 65, 65, 0.04);
  for (int k = 0; k < 50; ++k) cloud.positions.emplace_back(30.0f + 3.0f * k, -20.0f, 7.0f);
  const PointSpacing spacing = measure_point_spacing(cloud);
  EXPECT_NEAR(spacing.spacing, 0.01, 1e-6);
  EXPECT_NEAR(spacing.quantile_90, 0.04, 1e-6);
  // --threads 1 measures the same, bit for bit.
  const PointSpacing one_thread = measure_point_spacing(cloud, 1);
  EXPECT_EQ(one_thread.spacing, spacing.spacing);
  EXPECT_EQ(one_thread.quantile_10, spacing.quantile_10);
  EXPECT_EQ(one_thread.quantile_90, spacing.quantile_90);
  EXPECT_EQ(one_thread.samples, spacing.samples);
}

TEST(PointSpacing, RefusesCloudsWithoutTwoDistinctPositions) {
  PointCloud one;
  one.positions = {Eigen::Vector3f(1, 2, 3)};
  EXPECT_THROW(measure_point_spacing(one), std::invalid_argument);
  PointCloud same;
  same.positions.assign(10, Eigen::Vector3f(1, 2, 3));
  EXPECT_THROW(measure_point_spacing(same), std::invalid_argument);
}

// Acceptance (issue 12.2): a depth frame scanned from its own sensor keeps its
// points when the radius is the automatic one. The old fixed 0.01 did not.
TEST(PointSpacing, AutoRadiusKeepsAKinectFrameSeenFromItsSensor) {
  for (const double depth_step : {0.0, 0.002}) {
    const PointCloud frame = testing::kinect_like_frame(320, 240, 57.0, depth_step);
    const PointSpacing spacing = measure_point_spacing(frame);
    ScanOptions options;
    options.point_radius = kScanRadiusPerSpacing * spacing.spacing;
    const ScanResult result = scan_cloud(frame, {Eigen::Vector3d::Zero()}, options);
    EXPECT_GE(result.visible_fraction, 0.99) << "depth step " << depth_step;
    options.point_radius = 0.01;
    EXPECT_LT(scan_cloud(frame, {Eigen::Vector3d::Zero()}, options).visible_fraction, 0.99);
  }
}

}  // namespace
}  // namespace occlusion
