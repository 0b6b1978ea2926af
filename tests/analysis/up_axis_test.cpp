#include "occlusion/analysis/up_axis.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "occlusion/analysis/viewpoints.hpp"
#include "support/cloud_scenes.hpp"

namespace occlusion {
namespace {

// The room [0, 4] x [0, 3] x [0, 2.5] every 5 cm, z up.
PointCloud z_up_room() {
  PointCloud cloud;
  testing::add_box_grid(cloud, 80, 60, 50, 0.05);
  return cloud;
}

// The same room in a camera frame: x right, y down, z forward.
PointCloud camera_frame(const PointCloud& z_up) {
  PointCloud cloud = z_up;
  for (auto& p : cloud.positions) p = Eigen::Vector3f(p.x(), -p.z(), p.y());
  return cloud;
}

TEST(UpAxis, ParsesSignedAxes) {
  EXPECT_EQ(UpAxis::parse("+z").axis, 2);
  EXPECT_EQ(UpAxis::parse("z").sign, 1);
  const UpAxis down_y = UpAxis::parse("-Y");
  EXPECT_EQ(down_y.axis, 1);
  EXPECT_EQ(down_y.sign, -1);
  EXPECT_EQ(down_y.name(), "-y");
  EXPECT_TRUE(down_y.vector().isApprox(Eigen::Vector3d(0, -1, 0)));
  EXPECT_DOUBLE_EQ(down_y.height(Eigen::Vector3f(0, 2, 0)), -2.0);
  for (const char* bad : {"", "+", "w", "+zz", "up", "--z"}) {
    EXPECT_THROW(UpAxis::parse(bad), std::invalid_argument) << bad;
  }
}

TEST(UpAxis, ARoomAgreesWithItsUpAndACameraFrameDoesNot) {
  const PointCloud room = z_up_room();
  EXPECT_FALSE(check_up_axis(room.positions, UpAxis::parse("+z")));
  const PointCloud camera = camera_frame(room);
  EXPECT_FALSE(check_up_axis(camera.positions, UpAxis::parse("-y")));
  const auto message = check_up_axis(camera.positions, UpAxis::parse("+z"));
  ASSERT_TRUE(message);
  EXPECT_NE(message->find("perpendicular to y"), std::string::npos) << *message;
}

TEST(UpAxis, GridLiesAtMidHeightOverTheFloorPlanOfItsUpAxis) {
  const Eigen::Vector3d lo(0, -2.5, 0), hi(4, 0, 3);  // the camera-frame room
  const auto grid = grid_viewpoints(4, lo, hi, 1);
  ASSERT_EQ(grid.size(), 4u);
  for (const auto& p : grid) {
    EXPECT_DOUBLE_EQ(p.y(), -1.25);
    EXPECT_GT(p.x(), 0.0);
    EXPECT_LT(p.x(), 4.0);
    EXPECT_GT(p.z(), 0.0);
    EXPECT_LT(p.z(), 3.0);
  }
  // Floor plan axes z, x: cell centres at 30 % and 70 % of each.
  EXPECT_DOUBLE_EQ(grid[0].z(), 0.9);
  EXPECT_DOUBLE_EQ(grid[0].x(), 1.2);
  EXPECT_DOUBLE_EQ(grid[3].z(), 2.1);
  EXPECT_DOUBLE_EQ(grid[3].x(), 2.8);
  // z up (the default) is the grid it always was.
  const auto z_grid = grid_viewpoints(4, Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 3, 2));
  EXPECT_DOUBLE_EQ(z_grid[0].x(), 1.2);
  EXPECT_DOUBLE_EQ(z_grid[0].y(), 0.9);
  EXPECT_DOUBLE_EQ(z_grid[0].z(), 1.0);
  EXPECT_THROW(grid_viewpoints(4, lo, hi, 3), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
