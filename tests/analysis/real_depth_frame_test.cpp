// A real Kinect frame of a room at 1.5 to 3.5 m (PCL's pairwise tutorial,
// files/pcl/capture0001.pcd): its depths come in the Kinect's steps, which
// grow with the square of depth, and pixels side by side share a step, so
// its surfaces are staircases of flat treads. Every point was seen by the
// camera, so -fscan from the camera keeps it, at every range; and the noise
// the model reads there is the rounding's, known from the Kinect's optics.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

PointCloud capture() {
  return read_cloud(std::string(OCCLUSION_SOURCE_DIR) + "/files/pcl/capture0001.pcd");
}

// The share of the frame's points -fscan keeps from its camera, per 0.5 m
// of range, for the bands of 1,000 points or more.
void expect_kept_at_every_range(const PointCloud& frame) {
  const SurfelEstimate estimate = estimate_surfels(frame, {});
  ScanOptions options;
  options.surfels = &estimate;
  const ScanResult seen = scan_cloud(frame, {Eigen::Vector3d::Zero()}, options);
  // Before the rounding was read as noise: 90 % kept at 1.5-2 m, 71 % at
  // 2.5-3 m, 59 % beyond 3.5 m.
  constexpr double kBand = 0.5;
  std::vector<std::size_t> points(8, 0), kept(8, 0);
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const auto band = static_cast<std::size_t>(frame.positions[i].norm() / kBand);
    ASSERT_LT(band, points.size());
    ++points[band];
    kept[band] += seen.visible_count[i] > 0;
  }
  for (std::size_t band = 0; band < points.size(); ++band) {
    if (points[band] < 1000) continue;
    SCOPED_TRACE(band * kBand);
    EXPECT_GE(static_cast<double>(kept[band]), 0.995 * static_cast<double>(points[band]));
  }
}

TEST(RealDepthFrame, TheCameraKeepsItsPointsAtEveryRange) {
  const PointCloud frame = capture();
  ASSERT_EQ(frame.size(), 249647u);
  ASSERT_TRUE(frame.has_pixels());
  expect_kept_at_every_range(frame);
}

TEST(RealDepthFrame, AsABareArrayTheCameraStillKeepsThem) {
  // Without its grid (a frame whose missing depths were dropped, as PCL's
  // removeNaNFromPointCloud leaves it), its camera's pose kept: 61.9 % kept
  // before the treads were read from the points' neighbours.
  PointCloud frame = capture();
  frame.pixels.clear();
  frame.sensor.width = frame.sensor.height = 0;
  ASSERT_TRUE(frame.sensor.single_view());
  expect_kept_at_every_range(frame);
}

TEST(RealDepthFrame, TheNoiseReadIsTheKinectsRounding) {
  const PointCloud frame = capture();
  const SurfelEstimate estimate = estimate_surfels(frame, {});
  ASSERT_EQ(estimate.noise.stations.size(), 1u);
  // The Kinect rounds disparity to 1/8 pixel; with its focal length 525 px
  // and baseline 7.5 cm a step at depth z is z^2 / (8 * 525 * 0.075), and a
  // rounding's error is uniform over a step: sigma = step / sqrt(12). The
  // bins are by range, a little more than the depth off the image's centre.
  std::size_t bins = 0;
  for (const NoiseBin& bin : estimate.noise.stations[0].bins) {
    if (bin.points < 10000) continue;
    ++bins;
    const double z = 0.5 * (bin.range_lo + bin.range_hi);
    const double rounding = z * z / (8.0 * 525.0 * 0.075) / std::sqrt(12.0);
    SCOPED_TRACE(z);
    EXPECT_GT(bin.sigma, 0.6 * rounding);
    EXPECT_LT(bin.sigma, 1.4 * rounding);
  }
  EXPECT_GE(bins, 3u);
}

}  // namespace
}  // namespace occlusion
