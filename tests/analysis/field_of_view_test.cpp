#include "occlusion/analysis/field_of_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "occlusion/analysis/cloud_occlusion.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "support/kinect_frame.hpp"

namespace occlusion {
namespace {

constexpr double kHorizontal = 57.0;

double vertical_for(std::size_t width, std::size_t height) {
  const double half_tan = std::tan(0.5 * kHorizontal * M_PI / 180.0);
  return 2.0 * std::atan(half_tan * static_cast<double>(height) / static_cast<double>(width)) *
         180.0 / M_PI;
}

TEST(FieldOfView, MeasuredFromAnOrganisedFrameIsTheCamerasView) {
  const PointCloud frame = testing::kinect_like_frame(160, 120, kHorizontal);
  const FieldOfView view = measure_field_of_view(frame);
  EXPECT_NEAR(view.horizontal_degrees(), kHorizontal, 1e-4);
  EXPECT_NEAR(view.vertical_degrees(), vertical_for(160, 120), 1e-4);
  EXPECT_TRUE(view.contains({0, 0, 1}));
  EXPECT_FALSE(view.contains({0, 0, -1}));
  EXPECT_FALSE(view.contains({1, 0, 1}));  // 45 degrees off axis: outside 28.5
  EXPECT_TRUE(view.contains({0.5, 0, 1}));
}

TEST(FieldOfView, FollowsTheSensorPose) {
  PointCloud frame = testing::kinect_like_frame(40, 30, kHorizontal);
  // The sensor turned to look along +x from (1, 2, 3): move the points along.
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  frame.sensor.origin = Eigen::Vector3d(1, 2, 3);
  frame.sensor.orientation = turn;
  for (auto& p : frame.positions) {
    p = (turn * p.cast<double>() + frame.sensor.origin).cast<float>();
  }
  ASSERT_TRUE(frame.sensor.single_view());
  const FieldOfView view = measure_field_of_view(frame);
  EXPECT_NEAR(view.horizontal_degrees(), kHorizontal, 1e-3);
  EXPECT_TRUE(view.contains({1, 0, 0}));
  EXPECT_FALSE(view.contains({0, 0, 1}));
}

TEST(FieldOfView, FromAnglesAndRefusals) {
  const FieldOfView view = field_of_view_from_angles(SensorFrame{}, 90.0, 60.0);
  EXPECT_NEAR(view.horizontal_degrees(), 90.0, 1e-9);
  EXPECT_NEAR(view.vertical_degrees(), 60.0, 1e-9);
  EXPECT_TRUE(view.contains({0.99, 0, 1}));
  EXPECT_FALSE(view.contains({1.01, 0, 1}));
  EXPECT_THROW(field_of_view_from_angles(SensorFrame{}, 0.0, 60.0), std::invalid_argument);
  EXPECT_THROW(field_of_view_from_angles(SensorFrame{}, 90.0, 180.0), std::invalid_argument);
  PointCloud behind;
  behind.positions = {Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(0, 0, -1)};
  EXPECT_THROW(measure_field_of_view(behind), std::invalid_argument);
}

// A frame seen from its own sensor: every ray inside the view meets the
// frame's surface, so the level over those rays is 0, and the rays outside it
// are exactly those whose direction the frustum does not hold.
TEST(FieldOfView, CloudOcclusionCountsRaysOutsideTheViewApart) {
  const PointCloud frame = testing::kinect_like_frame(160, 120, kHorizontal);
  CloudOcclusionOptions options;
  // Wide enough that no ray inside the view slips between two pixels' points.
  options.point_radius = 2.0 * measure_point_spacing(frame).quantile_90;
  options.num_rays_per_vp = 20000;
  options.field_of_view = measure_field_of_view(frame);
  const std::vector<Eigen::Vector3d> sensor = {Eigen::Vector3d::Zero()};
  const CloudOcclusionResult result = compute_cloud_occlusion(frame, sensor, {}, options);

  const SphereDirections directions(options.sampling, options.num_rays_per_vp, options.seed, 0);
  std::size_t outside = 0;
  for (std::size_t k = 0; k < options.num_rays_per_vp; ++k) {
    outside += options.field_of_view->contains(directions(k)) ? 0 : 1;
  }
  EXPECT_EQ(result.outside_view_rays, outside);
  EXPECT_EQ(result.viewpoints[0].outside_view_rays, outside);
  EXPECT_EQ(result.hits + result.occlusion_rays + result.outside_view_rays, result.rays);
  EXPECT_EQ(result.occlusion_rays, 0u);
  EXPECT_EQ(result.occlusion_level, 0.0);

  // Without the view the rays outside it are occlusion rays (the old answer),
  // but for the few that graze the spheres of the frame's border points.
  options.field_of_view.reset();
  const CloudOcclusionResult all = compute_cloud_occlusion(frame, sensor, {}, options);
  EXPECT_EQ(all.hits, result.hits + (outside - all.occlusion_rays));
  EXPECT_LE(all.occlusion_rays, outside);
  EXPECT_GT(all.occlusion_rays, outside * 99 / 100);
}

}  // namespace
}  // namespace occlusion
