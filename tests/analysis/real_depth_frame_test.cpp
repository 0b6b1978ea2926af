// A real Kinect frame of a room at 1.5 to 3.5 m (PCL's pairwise tutorial,
// files/pcl/capture0001.pcd): its depths come in the Kinect's steps, which
// grow with the square of depth, and pixels side by side share a step, so
// its surfaces are staircases of flat treads. Every point was seen by the
// camera, so -fscan from the camera keeps it, at every range; and the noise
// the model reads there is the rounding's, known from the Kinect's optics.
// A stereo camera's frame, not tuned on (files/pcl/table_scene_mug_stereo_
// textured.pcd: PCL's tutorial scene, depths 0.69 to 2.59 m in sub-pixel
// disparity steps), keeps its points too, and its discs close the surfaces
// it saw: a ray between two neighbouring pixels' rays still meets them.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/core/surfel_octree.hpp"
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

PointCloud stereo_frame() {
  return read_cloud(std::string(OCCLUSION_SOURCE_DIR) +
                    "/files/pcl/table_scene_mug_stereo_textured.pcd");
}

TEST(RealDepthFrame, AStereoFrameNotTunedOnKeepsItsPointsAtEveryRange) {
  const PointCloud frame = stereo_frame();
  ASSERT_EQ(frame.size(), 209280u);
  ASSERT_TRUE(frame.has_pixels());
  expect_kept_at_every_range(frame);
}

TEST(RealDepthFrame, AStereoFramesDiscsCloseWhatItSaw) {
  // From the camera towards a random place between a pixel's point and its
  // right-hand neighbour's (both valid, within 2 % in depth: one surface),
  // to a quarter beyond them: the discs are met, or the frame would show
  // holes the camera never saw. And the rays to a quarter before them meet
  // nothing, or the frame's own discs would stand in front of its surfaces.
  const PointCloud frame = stereo_frame();
  const SurfelEstimate estimate = estimate_surfels(frame, {});
  const SurfelOctree tree(estimate.surfels, surfel_octree_options());
  std::vector<std::ptrdiff_t> at_pixel(640 * 480, -1);
  for (std::size_t i = 0; i < frame.size(); ++i) {
    at_pixel[frame.pixels[i]] = static_cast<std::ptrdiff_t>(i);
  }
  Rng rng(7);
  std::size_t pairs = 0, met_beyond = 0, met_before = 0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const std::uint32_t pixel = frame.pixels[i];
    if (pixel % 640 == 639 || at_pixel[pixel + 1] < 0) continue;
    const Eigen::Vector3f& a = frame.positions[i];
    const Eigen::Vector3f& b = frame.positions[static_cast<std::size_t>(at_pixel[pixel + 1])];
    if (std::abs(a.z() - b.z()) > 0.02f * a.z()) continue;
    ++pairs;
    const Eigen::Vector3f between = a + static_cast<float>(rng.uniform()) * (b - a);
    const float range = between.norm();
    const Eigen::Vector3f direction = between / range;
    met_beyond += tree.occluded(Ray{Eigen::Vector3f::Zero(), direction, 0.0f, 1.25f * range});
    met_before += tree.occluded(Ray{Eigen::Vector3f::Zero(), direction, 0.0f, 0.75f * range});
  }
  ASSERT_GT(pairs, 150000u);
  EXPECT_GE(static_cast<double>(met_beyond), 0.999 * static_cast<double>(pairs));
  EXPECT_LE(static_cast<double>(met_before), 0.001 * static_cast<double>(pairs));
}

}  // namespace
}  // namespace occlusion
