// The global shift: clouds far from the origin are read relative to a round
// shift chosen from their first point, and written back in their own frame
// in double, so positions survive to double precision (docs/formats.md).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

using testing::read_bytes;
using testing::ScratchDirectory;
using testing::write_text;

// UTM-like coordinates with millimetres, as a survey exports them.
const std::vector<std::string> kLines = {
    "500003.123 5400001.457 101.250",
    "500012.004 5400007.891 99.999",
    "499998.5 5399996.25 100.001",
    "500021.777 5400012.345 103.5",
    "500000 5400000 100",
};

std::vector<Eigen::Vector3d> parsed_lines() {
  std::vector<Eigen::Vector3d> points;
  for (const auto& line : kLines) {
    std::istringstream in(line);
    Eigen::Vector3d p;
    in >> p.x() >> p.y() >> p.z();
    points.push_back(p);
  }
  return points;
}

std::string utm_cloud(const ScratchDirectory& dir) {
  std::string text;
  for (const auto& line : kLines) text += line + "\n";
  write_text(dir.file("utm.txt"), text);
  return dir.file("utm.txt");
}

TEST(GlobalShift, ChosenFromTheFirstPointWhenFarOnly) {
  EXPECT_EQ(choose_global_shift({12.5, -40.0, 3.0}), Eigen::Vector3d::Zero());
  EXPECT_EQ(choose_global_shift({999.0, 0.0, 0.0}), Eigen::Vector3d::Zero());
  EXPECT_EQ(choose_global_shift({500003.123, 5400001.457, 101.25}),
            Eigen::Vector3d(500000.0, 5400000.0, 100.0));
  EXPECT_EQ(choose_global_shift({-1234.0, 49.0, 51.0}), Eigen::Vector3d(-1200.0, 0.0, 100.0));
  EXPECT_EQ(choose_global_shift({NAN, 5e6, 0.0}), Eigen::Vector3d::Zero());
}

TEST(GlobalShift, TextCloudIsReadShiftedInDouble) {
  const ScratchDirectory dir;
  const PointCloud cloud = read_cloud(utm_cloud(dir));
  EXPECT_EQ(cloud.shift, Eigen::Vector3d(500000.0, 5400000.0, 100.0));
  const auto expected = parsed_lines();
  ASSERT_EQ(cloud.size(), expected.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    // Local positions keep float's precision near zero, not at 5.4e6 ...
    EXPECT_NEAR(cloud.positions[i].y(), expected[i].y() - 5400000.0, 1e-6);
    // ... and the file's coordinates come back to double precision.
    EXPECT_EQ(cloud.original_position(i), expected[i]) << kLines[i];
  }
}

TEST(GlobalShift, CloudNearTheOriginIsNotShifted) {
  const ScratchDirectory dir;
  write_text(dir.file("room.txt"), "1.5 2 3\n40 -12 0.25\n");
  const PointCloud cloud = read_cloud(dir.file("room.txt"));
  EXPECT_FALSE(cloud.shifted());
  write_cloud(dir.file("room.ply"), cloud, {}, CloudFormat::kPlyAscii);
  EXPECT_NE(read_bytes(dir.file("room.ply")).find("property float x"), std::string::npos);
}

// Every writer puts the file's coordinates back, in double: read again, the
// positions equal the input's to double precision, with the same shift.
TEST(GlobalShift, EveryFormatRoundTripsTheFileCoordinates) {
  const ScratchDirectory dir;
  const PointCloud cloud = read_cloud(utm_cloud(dir));
  const auto expected = parsed_lines();
  const struct {
    CloudFormat format;
    const char* name;
  } cases[] = {{CloudFormat::kPlyAscii, "a.ply"},
               {CloudFormat::kPlyBinary, "b.ply"},
               {CloudFormat::kPcdAscii, "a.pcd"},
               {CloudFormat::kPcdBinary, "b.pcd"},
               {CloudFormat::kPcdBinaryCompressed, "c.pcd"}};
  for (const auto& c : cases) {
    write_cloud(dir.file(c.name), cloud, {}, c.format);
    const PointCloud back = read_cloud(dir.file(c.name));
    EXPECT_EQ(back.shift, cloud.shift) << c.name;
    ASSERT_EQ(back.size(), expected.size());
    for (std::size_t i = 0; i < back.size(); ++i) {
      EXPECT_EQ(back.positions[i], cloud.positions[i]) << c.name << ' ' << i;
      EXPECT_EQ(back.original_position(i), expected[i]) << c.name << ' ' << kLines[i];
    }
  }
  // In ascii the numbers are the input's own.
  const std::string ply = read_bytes(dir.file("a.ply"));
  EXPECT_NE(ply.find("property double x"), std::string::npos);
  EXPECT_NE(ply.find("\n500003.123 5400001.457 101.25\n"), std::string::npos) << ply;
  const std::string pcd = read_bytes(dir.file("a.pcd"));
  EXPECT_NE(pcd.find("SIZE 8 8 8"), std::string::npos) << pcd;
  EXPECT_NE(pcd.find("\n500012.004 5400007.891 99.999\n"), std::string::npos) << pcd;
}

// A first point far from the rest: its shift would only move the loss of
// precision onto the others, so the cloud is read without one.
TEST(GlobalShift, AShiftThatWouldNotHelpIsDropped) {
  const ScratchDirectory dir;
  write_text(dir.file("stray.txt"), "0.5 -2500000 7\n0.1 0.1 -0.2\n2 2.25 1\n");
  const PointCloud cloud = read_cloud(dir.file("stray.txt"));
  EXPECT_FALSE(cloud.shifted());
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(0.1f, 0.1f, -0.2f));
}

TEST(GlobalShift, AGivenShiftIsUsed) {
  const ScratchDirectory dir;
  CloudReadOptions options;
  options.shift = Eigen::Vector3d(500100.0, 5400000.0, 0.0);
  const PointCloud cloud = read_cloud(utm_cloud(dir), options);
  EXPECT_EQ(cloud.shift, *options.shift);
  EXPECT_EQ(cloud.original_position(0), parsed_lines()[0]);
  options.shift = Eigen::Vector3d::Zero();  // zero: none, whatever the coordinates
  EXPECT_FALSE(read_cloud(utm_cloud(dir), options).shifted());
}

// Finite points that overflow float once the first point's shift is
// subtracted (the corners of a +-2e38 cube: all but the first corner's) were
// dropped as if NaN, and a job answered on 25 of 200 points. Every format
// refuses such a cloud instead, saying how many and why.
TEST(GlobalShift, PointsThatOverflowFloatOnceShiftedAreRefused) {
  const ScratchDirectory dir;
  PointCloud corners;
  for (int i = 0; i < 200; ++i) {
    const int c = i % 8;
    corners.positions.emplace_back(c & 1 ? 2e38f : -2e38f, c & 2 ? 2e38f : -2e38f,
                                   c & 4 ? 2e38f : -2e38f);
  }
  for (const char* name : {"corners.ply", "corners.pcd"}) {
    write_cloud(dir.file(name), corners);
    testing::expect_input_error([&] { read_cloud(dir.file(name)); }, name, 0,
                                "175 of 200 points have finite coordinates that float cannot hold");
  }
  std::string text;
  for (int i = 0; i < 200; ++i) {
    const int c = i % 8;
    text += std::string(c & 1 ? "2e38 " : "-2e38 ") + (c & 2 ? "2e38 " : "-2e38 ") +
            (c & 4 ? "2e38\n" : "-2e38\n");
  }
  write_text(dir.file("corners.txt"), text);
  testing::expect_input_error([&] { read_cloud(dir.file("corners.txt")); }, "corners.txt", 0,
                              "once the global shift");
  // Beyond float without any shift: refused too, not dropped.
  write_text(dir.file("beyond.txt"), "0 0 0\n1 0 0\n0 1 0\n1e39 0 0\n");
  testing::expect_input_error([&] { read_cloud(dir.file("beyond.txt")); }, "beyond.txt", 0,
                              "1 of 4 points have finite coordinates that float cannot hold");
  // A NaN point is still dropped and counted.
  write_text(dir.file("nan.txt"), "0 0 0\nnan 0 0\n0 1 0\n");
  CloudReadReport report;
  EXPECT_EQ(read_cloud(dir.file("nan.txt"), {}, &report).size(), 2u);
  EXPECT_EQ(report.dropped_nan, 1u);
}

// Every file of an S3DIS folder takes the first file's shift, though its own
// first point would round to another one.
TEST(GlobalShift, AnS3disRoomHasOneShift) {
  const ScratchDirectory dir;
  std::filesystem::create_directories(dir.file("room/Annotations"));
  write_text(dir.file("room/Annotations/floor_1.txt"),
             "500049 5400000 100 1 2 3\n500049.5 5400000 100 1 2 3\n500049 5400000.5 100 1 2 3\n");
  write_text(dir.file("room/Annotations/wall_1.txt"),
             "500051 5400000 100 1 2 3\n500051 5400000 101 1 2 3\n500051 5400000.5 101 1 2 3\n");
  const PointCloud cloud = read_cloud(dir.file("room"));
  EXPECT_EQ(cloud.shift, Eigen::Vector3d(500000.0, 5400000.0, 100.0));
  ASSERT_EQ(cloud.size(), 6u);
  EXPECT_EQ(cloud.original_position(3), Eigen::Vector3d(500051.0, 5400000.0, 100.0));
  EXPECT_FLOAT_EQ(cloud.positions[3].x(), 51.0f);
}

}  // namespace
}  // namespace occlusion
