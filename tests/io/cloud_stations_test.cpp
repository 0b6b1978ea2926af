// Stations, each point's station and intensity survive every cloud writer and
// its reader: an -fscan output of a laser scan keeps what the scan recorded.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

// Two stations of a cloud far from the origin (so shifted), one with a grid
// and a turn about z, names that need escaping.
PointCloud scanned_cloud() {
  PointCloud cloud;
  cloud.shift = Eigen::Vector3d(500000, 5400000, 0);
  cloud.positions = {{1.5f, 2.0f, 0.25f}, {-3.0f, 0.5f, 1.0f}, {0.125f, -1.0f, 2.0f}};
  cloud.intensities = {0.5f, 1234.25f, -0.0625f};
  Station a{"Scan \"A\" \\ north", {}};
  a.frame.origin = Eigen::Vector3d(0.25, -1.5, 1.625);
  a.frame.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.75, Eigen::Vector3d::UnitZ()));
  a.frame.width = 8640;
  a.frame.height = 3600;
  Station b{"second\tline\nbreak", {}};
  b.frame.origin = Eigen::Vector3d(4, 5, 1.5);
  cloud.stations = {a, b};
  cloud.station_ids = {1, 0, 1};
  return cloud;
}

class CloudStations : public ::testing::TestWithParam<CloudFormat> {};

TEST_P(CloudStations, StationsIdsAndIntensitiesComeBack) {
  testing::ScratchDirectory dir;
  const bool ply = GetParam() == CloudFormat::kPlyAscii || GetParam() == CloudFormat::kPlyBinary;
  const std::string path = dir.file(ply ? "s.ply" : "s.pcd");
  const PointCloud cloud = scanned_cloud();
  write_cloud(path, cloud, {}, GetParam());
  CloudReadReport report;
  const PointCloud back = read_cloud(path, {}, &report);
  EXPECT_TRUE(report.extra_fields.empty()) << "intensity and scan are no extra fields";
  EXPECT_EQ(back.shift, cloud.shift);
  EXPECT_EQ(back.intensities, cloud.intensities);
  EXPECT_EQ(back.station_ids, cloud.station_ids);
  ASSERT_EQ(back.stations.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    const SensorFrame& want = cloud.stations[s].frame;
    const SensorFrame& got = back.stations[s].frame;
    EXPECT_EQ(back.stations[s].name, cloud.stations[s].name);
    // The origin is held in the local frame, as positions are.
    EXPECT_NEAR((got.origin - want.origin).norm(), 0.0, 1e-9) << s;
    EXPECT_NEAR(got.orientation.angularDistance(want.orientation), 0.0, 1e-12) << s;
    EXPECT_EQ(got.width, want.width);
    EXPECT_EQ(got.height, want.height);
  }
  EXPECT_NO_THROW(back.validate());
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, CloudStations,
                         ::testing::Values(CloudFormat::kPlyAscii, CloudFormat::kPlyBinary,
                                           CloudFormat::kPcdAscii, CloudFormat::kPcdBinary,
                                           CloudFormat::kPcdBinaryCompressed));

TEST(CloudStations, PlyHeaderRecordsStationsInTheFilesFrame) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("h.ply");
  write_cloud(path, scanned_cloud(), {}, CloudFormat::kPlyAscii);
  const std::string text = testing::read_bytes(path);
  // Origin + shift; quotes, backslashes, tabs and newlines escaped.
  EXPECT_NE(text.find("comment station \"second\\tline\\nbreak\" 500004 5400005 1.5 1 0 0 0 0 0\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("comment station \"Scan \\\"A\\\" \\\\ north\" 500000.25 5399998.5 1.625 "),
            std::string::npos)
      << text;
  // CloudCompare loads `intensity` as is, and other values with the scalar_ prefix.
  EXPECT_NE(text.find("property float intensity\n"), std::string::npos);
  EXPECT_NE(text.find("property int scalar_scan\n"), std::string::npos);
}

const char* kHeader =
    "ply\nformat ascii 1.0\n"
    "comment station \"one\" 0 0 0 1 0 0 0 0 0\n"
    "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
    "property int scan\nend_header\n";

TEST(CloudStations, PlyScanValueMustNameAStation) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bad.ply");
  testing::write_text(path, std::string(kHeader) + "0 0 0 0\n1 1 1 1\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.ply", 11,
                              "scan value 1 names no station (the header records 1)");
}

TEST(CloudStations, PlyMalformedStationCommentIsRefusedWithItsLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("comment.ply");
  std::string header = kHeader;
  header.replace(header.find("\"one\""), 5, "\"one");
  testing::write_text(path, header + "0 0 0 0\n");
  testing::expect_input_error([&] { read_cloud(path); }, "comment.ply", 3, "no closing quote");
  std::string rotated = kHeader;
  rotated.replace(rotated.find(" 1 0 0 0 0 0"), 12, " 2 0 0 0 0 0");
  testing::write_text(path, rotated + "0 0 0 0\n");
  testing::expect_input_error([&] { read_cloud(path); }, "comment.ply", 3, "unit quaternion");
}

TEST(CloudStations, ScanWithoutStationCommentsIsAnOrdinaryField) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("plain.ply");
  std::string header = kHeader;
  header.erase(header.find("comment station"), header.find("element") - header.find("comment"));
  testing::write_text(path, header + "0 0 0 7\n1 1 1 9\n");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  EXPECT_FALSE(cloud.has_station_ids());
  ASSERT_EQ(report.extra_fields.size(), 1u);
  EXPECT_EQ(report.extra_fields[0].name, "scan");
  EXPECT_EQ(report.extra_fields[0].values, (std::vector<float>{7, 9}));
}

TEST(CloudStations, PcdIntensityIsPclsField) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("i.pcd");
  PointCloud cloud;
  cloud.positions = {{1, 2, 3}};
  cloud.intensities = {0.75f};
  write_cloud(path, cloud, {}, CloudFormat::kPcdAscii);
  const std::string text = testing::read_bytes(path);
  EXPECT_NE(text.find("FIELDS x y z intensity\n"), std::string::npos) << text;
  EXPECT_EQ(read_cloud(path).intensities, cloud.intensities);
}

TEST(CloudStations, IntensityAndScanAreNoExtraFieldNames) {
  testing::ScratchDirectory dir;
  const PointCloud cloud = testing::labelled_cloud();
  EXPECT_THROW(write_cloud(dir.file("x.ply"), cloud, {{"intensity", {1, 2, 3, 4}, false}}),
               std::invalid_argument);
  EXPECT_THROW(write_cloud(dir.file("x.ply"), cloud, {{"scan", {1, 2, 3, 4}, true}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
