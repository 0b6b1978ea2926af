// 3DTK's .3d scans (files/3dtk/, SOURCES.md there), read with and without
// their .pose files, checked against the pose files' numbers worked by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

const std::string kFolder = std::string(OCCLUSION_SOURCE_DIR) + "/files/3dtk/";
constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3d station_position(const PointCloud& cloud, std::size_t station) {
  return cloud.to_original(cloud.stations.at(station).frame.origin);
}

// 3DTK's EulerToMatrix4 written out (angles in degrees, column vectors), then
// its frame (cm; x right, y up, z forward) to ours (m; x forward, y left, z up).
Eigen::Vector3d by_hand(const Eigen::Vector3d& point_cm, const Eigen::Vector3d& t_cm,
                        const Eigen::Vector3d& degrees) {
  const double sx = std::sin(degrees.x() * kPi / 180), cx = std::cos(degrees.x() * kPi / 180);
  const double sy = std::sin(degrees.y() * kPi / 180), cy = std::cos(degrees.y() * kPi / 180);
  const double sz = std::sin(degrees.z() * kPi / 180), cz = std::cos(degrees.z() * kPi / 180);
  Eigen::Matrix3d r;
  r << cy * cz, -cy * sz, sy,                                     //
      sx * sy * cz + cx * sz, -sx * sy * sz + cx * cz, -sx * cy,  //
      -cx * sy * cz + sx * sz, cx * sy * sz + sx * cz, cx * cy;
  const Eigen::Vector3d world = r * point_cm + t_cm;
  return Eigen::Vector3d(world.z(), -world.x(), world.y()) / 100.0;
}

// scan001.pose: "-3.10605 -7.50803 156.917" cm and "1.35694 -0.852409 -0.56224"
// degrees; scan001.3d's first line "10.2 0 2.84217e-14".
TEST(UosScanReader, ScanWithItsPoseIsPlacedAndItsStationAtThePose) {
  const PointCloud cloud = read_cloud(kFolder + "scan001.3d");
  ASSERT_EQ(cloud.size(), 81360u);
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_EQ(cloud.stations[0].name, "scan001");
  EXPECT_LT((station_position(cloud, 0) - Eigen::Vector3d(1.56917, 0.0310605, -0.0750803)).norm(),
            1e-6);
  ASSERT_EQ(cloud.station_ids.size(), cloud.size());
  EXPECT_EQ(cloud.station_ids.back(), 0);
  const Eigen::Vector3d t(-3.10605, -7.50803, 156.917), angles(1.35694, -0.852409, -0.56224);
  const Eigen::Vector3d first = by_hand({10.2, 0, 2.84217e-14}, t, angles);
  EXPECT_LT((cloud.original_position(0) - first).norm(), 1e-6) << cloud.original_position(0);
}

TEST(UosScanReader, ScanWithoutPoseIsInTheScannersFrame) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("scan001.3d");
  std::filesystem::copy_file(kFolder + "scan001.3d", path);
  const PointCloud cloud = read_cloud(path);
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_EQ(station_position(cloud, 0), Eigen::Vector3d::Zero());
  // (10.2, 0, 2.84217e-14) cm: 10.2 cm to the scanner's right, -y in our frame.
  EXPECT_LT((cloud.original_position(0) - Eigen::Vector3d(2.84217e-16, -0.102, 0)).norm(), 1e-7);
}

TEST(UosScanReader, ResolutionLineCommentsAndLayouts) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("scan007.3d");
  testing::write_text(path, "640 x 480\n# a comment\n100 200 300\n-1 -2 -3 # trailing\n");
  const PointCloud cloud = read_cloud(path);
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_LT((cloud.original_position(0) - Eigen::Vector3d(3, -1, 2)).norm(), 1e-7);

  // Six columns are uos_rgb or uos_normal: refused, with the project's "layout" named.
  testing::write_text(path, "1 2 3 255 0 0\n");
  testing::expect_input_error([&] { read_cloud(path); }, "scan007.3d", 1, "\"layout\"");
  testing::write_text(path, "1 2 3\n1 2\n");
  testing::expect_input_error([&] { read_cloud(path); }, "scan007.3d", 2, "2 columns");
  testing::write_text(path, "1 2 3\n1 2 z\n");
  testing::expect_input_error([&] { read_cloud(path); }, "scan007.3d", 2, "not a number");
}

TEST(UosScanReader, AMalformedPoseIsAnErrorNotAnUnplacedScan) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("scan000.3d"), "100 200 300\n");
  testing::write_text(dir.file("scan000.pose"), "1 2 3\n4 5\n");
  testing::expect_input_error([&] { read_cloud(dir.file("scan000.3d")); }, "scan000.pose", 0,
                              "6 numbers");
}

}  // namespace
}  // namespace occlusion
