// A depth frame and LAS files through the CLI, as a user gives them: the
// frame's descriptor path, read by read_cloud like any cloud.

#include <gtest/gtest.h>

#include <cmath>

#include "cli/run_cli.hpp"
#include "support/kinect_frame.hpp"
#include "support/png_writer.hpp"

namespace occlusion {
namespace {

using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;

// The Kinect-like room corner (support/kinect_frame.hpp) as a depth PNG in
// millimetres, with its intrinsics, seen from `pose_tum`.
std::string write_room_frame(const TempDir& dir, const std::string& pose_tum) {
  constexpr std::size_t kWidth = 160, kHeight = 120;
  const PointCloud frame = testing::kinect_like_frame(kWidth, kHeight, 57.0);
  std::vector<std::uint16_t> depth;
  for (const Eigen::Vector3f& p : frame.positions) {
    depth.push_back(static_cast<std::uint16_t>(std::lround(p.z() * 1000.0)));
  }
  testing::write_depth_png(dir.file("room_depth.png"), kWidth, kHeight, depth);
  // kinect_like_frame puts pixel (u, v)'s centre at u + 0.5 - width / 2.
  const double focal = 0.5 * kWidth / std::tan(0.5 * 57.0 * M_PI / 180.0);
  dir.write("room.frame.json",
            "{\"depth\": \"room_depth.png\", \"depth_scale\": 1000,\n"
            " \"intrinsics\": {\"fx\": " +
                std::to_string(focal) + ", \"fy\": " + std::to_string(focal) +
                ", \"cx\": 79.5, \"cy\": 59.5},\n \"pose_tum\": " + pose_tum + "}\n");
  return dir.file("room.frame.json");
}

TEST(DepthFrameCli, ScanFromItsOwnCameraKeepsItsPoints) {
  const TempDir dir;
  // The camera at (10, 20, 1.5), turned 30 degrees about the world's z.
  const double half = 15.0 * M_PI / 180.0;
  const std::string frame =
      write_room_frame(dir, "[10, 20, 1.5, 0, 0, " + std::to_string(std::sin(half)) + ", " +
                                std::to_string(std::cos(half)) + "]");
  const Json::Value scan = run_json("-fscan '" + frame + "' --viewpoint 10,20,1.5");
  EXPECT_EQ(scan["points"].asUInt64(), 160u * 120u);
  EXPECT_GE(scan["visible_fraction"].asDouble(), 0.99);
  const Json::Value poc =
      run_json("-poc '" + frame + "' --viewpoint 10,20,1.5 --num-rays-per-vp 2000");
  EXPECT_EQ(poc["field_of_view"]["source"].asString(), "organised frame 160 x 120");
  EXPECT_NEAR(poc["field_of_view"]["horizontal_degrees"].asDouble(), 57.0, 0.1);
}

TEST(DepthFrameCli, BadInputsExitWithCode3) {
  const TempDir dir;
  const std::string frame = write_room_frame(dir, "[0, 0, 0, 0, 0, 0, 1]");
  const auto bare = run_cli("-fscan '" + dir.file("room_depth.png") + "' --viewpoint 0,0,0");
  EXPECT_EQ(bare.exit_code, 3);
  EXPECT_NE(bare.err.find(".frame.json"), std::string::npos) << bare.err;
  const auto laz = run_cli("-poc '" + kSource + "/files/las/simple.laz'");
  EXPECT_EQ(laz.exit_code, 3);
  EXPECT_NE(laz.err.find("LASzip-compressed"), std::string::npos) << laz.err;
}

TEST(LasCli, ScansAPublicLasFileFromAViewpoint) {
  // laspy's simple.las: 1,065 points in State Plane feet, far from the origin.
  const Json::Value scan =
      run_json("-fscan '" + kSource + "/files/las/simple.las' --viewpoint 637300,851200,600");
  EXPECT_EQ(scan["points"].asUInt64(), 1065u);
  EXPECT_GT(scan["visible_fraction"].asDouble(), 0.0);
}

}  // namespace
}  // namespace occlusion
