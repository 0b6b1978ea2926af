// A depth frame and LAS files through the CLI, as a user gives them: the
// frame's descriptor path, read by read_cloud like any cloud.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cli/run_cli.hpp"
#include "occlusion/io/cloud_io.hpp"
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

// The real Kinect frame files/pcl/mosd_learn25.pcd (640 x 480, metres in the
// camera frame, a table top up to 1.46 m away) as a depth PNG of every 4th
// pixel of every 4th row (160 x 120, the intrinsics scaled with it), each
// depth z stored as encode(z): as the datasets store their frames.
template <class Encode>
std::string write_kinect_frame(const TempDir& dir, const std::string& name, double depth_scale,
                               Encode encode) {
  const PointCloud kinect = read_cloud(kSource + "/files/pcl/mosd_learn25.pcd");
  const std::size_t width = kinect.sensor.width;
  std::vector<std::uint16_t> depth(160 * 120, 0);
  for (std::size_t i = 0; i < kinect.size(); ++i) {
    const std::size_t u = kinect.pixels[i] % width;
    const std::size_t v = kinect.pixels[i] / width;
    if (u % 4 != 0 || v % 4 != 0) continue;
    depth[(v / 4) * 160 + u / 4] = encode(kinect.positions[i].z());
  }
  testing::write_depth_png(dir.file(name + ".png"), 160, 120, depth);
  // The ROS default Kinect intrinsics (525, 525, 319.5, 239.5), a quarter.
  dir.write(name + ".frame.json", "{\"depth\": \"" + name +
                                      ".png\", \"depth_scale\": " + std::to_string(depth_scale) +
                                      ",\n \"intrinsics\": {\"fx\": 131.25, \"fy\": 131.25, "
                                      "\"cx\": 79.875, \"cy\": 59.875}}\n");
  return dir.file(name + ".frame.json");
}

std::uint16_t millimetres(float z) {
  return static_cast<std::uint16_t>(std::lround(z * 1000.0));
}

// SUN RGB-D rotates each millimetre value's bits left by three places: read
// as they are, depths come out 8 times too far.
std::uint16_t sun_rgbd(std::uint16_t mm) {
  return static_cast<std::uint16_t>((mm << 3) | (mm >> 13));
}

const std::string kFarWarning = "farther than indoor depth cameras measure";

// What a user's run says of a frame: the warnings on stderr and in the JSON.
std::vector<std::string> frame_warnings(const std::string& frame) {
  const testing::CliRun run = run_cli("-fscan '" + frame + "' --viewpoint 0,0,0 --json -q");
  EXPECT_EQ(run.exit_code, 0) << frame << "\n" << run.err;
  std::vector<std::string> warnings;
  const Json::Value json = testing::parse_json(run.out);
  for (const auto& w : json["warnings"]) {
    warnings.push_back(w.asString());
    EXPECT_NE(run.err.find(w.asString()), std::string::npos) << run.err;
  }
  return warnings;
}

bool warns_of_far_depths(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) {
    if (w.find(kFarWarning) != std::string::npos) return true;
  }
  return false;
}

TEST(DepthFrameCli, RealKinectFramesDrawNoWarningOfFarDepths) {
  const TempDir dir;
  // In millimetres (ScanNet, NYU, SUN RGB-D once its bits are put back) and
  // at TUM's 5000 values a metre.
  EXPECT_TRUE(frame_warnings(write_kinect_frame(dir, "mm", 1000, millimetres)).empty());
  EXPECT_TRUE(frame_warnings(write_kinect_frame(dir, "tum", 5000, [](float z) {
                return static_cast<std::uint16_t>(std::lround(z * 5000.0));
              })).empty());
  // Its bits rotated it reads up to 11.7 m, nearer than any sensor's reach:
  // nothing there is untrue, so nothing is said (docs/formats.md).
  EXPECT_FALSE(warns_of_far_depths(frame_warnings(
      write_kinect_frame(dir, "sun", 1000, [](float z) { return sun_rgbd(millimetres(z)); }))));
}

TEST(DepthFrameCli, ARotatedSunRgbdFrameIsWarnedOfNamingTheFarDepths) {
  const TempDir dir;
  // The Kinect-like room corner, its far wall 3.6 m away: as it is, nothing
  // to say; its bits rotated as SUN RGB-D's, depths up to 29 m.
  EXPECT_FALSE(warns_of_far_depths(frame_warnings(write_room_frame(dir, "[0, 0, 0, 0, 0, 0, 1]"))));
  const PointCloud room = testing::kinect_like_frame(160, 120, 57.0);
  std::vector<std::uint16_t> rotated;
  std::size_t beyond = 0;
  for (const Eigen::Vector3f& p : room.positions) {
    rotated.push_back(sun_rgbd(millimetres(p.z())));
    beyond += rotated.back() > kMaxIndoorDepthMetres * 1000 ? 1 : 0;
  }
  ASSERT_GT(beyond, 0u);
  testing::write_depth_png(dir.file("room_depth.png"), 160, 120, rotated);
  const std::vector<std::string> warnings = frame_warnings(dir.file("room.frame.json"));
  ASSERT_TRUE(warns_of_far_depths(warnings)) << ::testing::PrintToString(warnings);
  // Reading's warnings come first.
  EXPECT_NE(warnings[0].find(kFarWarning), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find(std::to_string(beyond) + " of 19200 depths"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("SUN RGB-D"), std::string::npos) << warnings[0];
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
