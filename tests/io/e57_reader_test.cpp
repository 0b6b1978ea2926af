// The E57 reader against files the test writer makes (support/e57_writer):
// known points, poses, field types and packet layouts, so every position,
// colour, station and error is checked against a value worked out by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "cloud_test_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "scratch_directory.hpp"
#include "support/e57_writer.hpp"

namespace occlusion {
namespace {

using test::E57FileSpec;
using test::E57ScanSpec;

constexpr double kPi = 3.14159265358979323846;

E57ScanSpec cartesian_scan(const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> x, y, z;
  for (const Eigen::Vector3d& p : points) {
    x.push_back(p.x());
    y.push_back(p.y());
    z.push_back(p.z());
  }
  E57ScanSpec scan;
  scan.fields = {test::e57_double("cartesianX", x), test::e57_double("cartesianY", y),
                 test::e57_double("cartesianZ", z)};
  return scan;
}

PointCloud read_spec(const testing::ScratchDirectory& dir, const E57FileSpec& spec,
                     CloudReadReport* report = nullptr) {
  const std::string path = dir.file("scan.e57");
  test::write_e57(path, spec);
  return read_cloud(path, {}, report);
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void expect_near(const Eigen::Vector3f& actual, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
  EXPECT_NEAR(actual.z(), expected.z(), tolerance);
}

TEST(E57Reader, CartesianDoublesOfOneScan) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan = cartesian_scan({{0.125, -2.5, 3.0}, {1.0 / 3.0, 0.1, -7.25}, {9, 8, 7}});
  scan.name = "north corner";
  const PointCloud cloud = read_spec(dir, {{scan}, ""});
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.positions[0], Eigen::Vector3f(0.125f, -2.5f, 3.0f));
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(1.0f / 3.0f, 0.1f, -7.25f));
  EXPECT_EQ(cloud.positions[2], Eigen::Vector3f(9, 8, 7));
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_EQ(cloud.stations[0].name, "north corner");
  EXPECT_EQ(cloud.stations[0].frame.origin, Eigen::Vector3d::Zero());
  EXPECT_EQ(cloud.stations[0].frame.width, 0u);
  EXPECT_EQ(cloud.station_ids, (std::vector<std::int32_t>{0, 0, 0}));
  EXPECT_FALSE(cloud.has_colours());
  EXPECT_FALSE(cloud.has_intensities());
  EXPECT_FALSE(cloud.sensor.single_view());  // stations only; the sensor is another's decision
  EXPECT_FALSE(cloud.shifted());
}

TEST(E57Reader, PoseRotatesThenTranslates) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan = cartesian_scan({{1, 0, 0}, {0, 2, 0}, {0, 0, 3}});
  // 90 degrees about z: x goes to y, y to -x.
  scan.rotation = Eigen::Quaterniond(std::cos(kPi / 4), 0, 0, std::sin(kPi / 4));
  scan.translation = Eigen::Vector3d(10, 20, 30);
  const PointCloud cloud = read_spec(dir, {{scan}, ""});
  ASSERT_EQ(cloud.size(), 3u);
  expect_near(cloud.positions[0], {10, 21, 30}, 1e-5);
  expect_near(cloud.positions[1], {8, 20, 30}, 1e-5);
  expect_near(cloud.positions[2], {10, 20, 33}, 1e-5);
  const Station& station = cloud.stations.at(0);
  EXPECT_EQ(station.frame.origin, Eigen::Vector3d(10, 20, 30));
  EXPECT_NEAR(station.frame.orientation.angularDistance(*scan.rotation), 0.0, 1e-12);
  // The orientation maps the scanner's frame into the file's: its x axis is the file's y.
  EXPECT_NEAR(
      (station.frame.orientation * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 0.0,
      1e-12);
}

TEST(E57Reader, SphericalCoordinates) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan;
  scan.fields = {test::e57_double("sphericalRange", {2, 1, 3, 2}),
                 test::e57_double("sphericalAzimuth", {0, kPi / 2, 1.0, kPi}),
                 test::e57_single("sphericalElevation", {0, 0, kPi / 2, kPi / 4})};
  scan.translation = Eigen::Vector3d(0, 0, 1.5);
  const PointCloud cloud = read_spec(dir, {{scan}, ""});
  ASSERT_EQ(cloud.size(), 4u);
  expect_near(cloud.positions[0], {2, 0, 1.5}, 1e-6);
  expect_near(cloud.positions[1], {0, 1, 1.5}, 1e-6);
  expect_near(cloud.positions[2], {0, 0, 4.5}, 1e-6);
  expect_near(cloud.positions[3], {-std::sqrt(2.0), 0, 1.5 + std::sqrt(2.0)}, 1e-6);
}

TEST(E57Reader, ScaledIntegersOfOddWidthsAcrossPackets) {
  const testing::ScratchDirectory dir;
  // 11, 13 and 34 bits, a constant field of 0 bits between them, 7 data
  // packets cut unevenly through the values, an empty and an index packet first.
  std::vector<std::int64_t> x, y, z, constant;
  for (std::int64_t i = 0; i < 500; ++i) {
    x.push_back((i * 37) % 2001 - 1000);
    y.push_back((i * 4099) % 8191);
    z.push_back((i * 1000003) % 1800001 - 900000);
    constant.push_back(7);
  }
  E57ScanSpec scan;
  scan.fields = {test::e57_scaled("cartesianX", -1000, 1000, 0.001, 5.0, x),
                 test::e57_integer("returnIndex", 7, 7, constant),
                 test::e57_scaled("cartesianY", 0, 8190, 0.5, 0.0, y),
                 test::e57_scaled("cartesianZ", -(std::int64_t{1} << 33), std::int64_t{1} << 33,
                                  0.001, 0.0, z)};
  scan.packets = 7;
  scan.filler_packets = true;
  const PointCloud cloud = read_spec(dir, {{scan}, ""});
  ASSERT_EQ(cloud.size(), 500u);
  for (std::size_t i = 0; i < 500; ++i) {
    // The E57 definition: value = raw * scale + offset.
    const Eigen::Vector3f expected(static_cast<float>(static_cast<double>(x[i]) * 0.001 + 5.0),
                                   static_cast<float>(static_cast<double>(y[i]) * 0.5),
                                   static_cast<float>(static_cast<double>(z[i]) * 0.001));
    ASSERT_EQ(cloud.positions[i], expected) << "point " << i;
  }
}

TEST(E57Reader, ColourAndIntensityScaledByTheirLimits) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan = cartesian_scan({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  scan.fields.push_back(test::e57_integer("colorRed", 0, 65535, {65535, 0, 32768}));
  scan.fields.push_back(test::e57_integer("colorGreen", 0, 65535, {0, 65535, 257}));
  scan.fields.push_back(test::e57_integer("colorBlue", 0, 65535, {257 * 10, 257 * 200, 65535}));
  scan.fields.push_back(test::e57_integer("intensity", 0, 2047, {0, 2047, 1023}));
  scan.extra_xml =
      "<colorLimits type=\"Structure\"><colorRedMinimum type=\"Integer\"/>"
      "<colorRedMaximum type=\"Integer\">65535</colorRedMaximum>"
      "<colorGreenMinimum type=\"Integer\">0</colorGreenMinimum>"
      "<colorGreenMaximum type=\"Integer\">65535</colorGreenMaximum>"
      "<colorBlueMinimum type=\"Integer\"/><colorBlueMaximum type=\"Integer\">65535"
      "</colorBlueMaximum></colorLimits>"
      "<intensityLimits type=\"Structure\"><intensityMinimum type=\"Float\">0</intensityMinimum>"
      "<intensityMaximum type=\"Float\">2047</intensityMaximum></intensityLimits>";
  const PointCloud cloud = read_spec(dir, {{scan}, ""});
  ASSERT_EQ(cloud.size(), 3u);
  ASSERT_TRUE(cloud.has_colours());
  // 32768 / 65535 * 255 = 127.50 -> 128; 257 / 65535 * 255 = 1.
  EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{255, 0, 10}));
  EXPECT_EQ(cloud.colours[1], (std::array<std::uint8_t, 3>{0, 255, 200}));
  EXPECT_EQ(cloud.colours[2], (std::array<std::uint8_t, 3>{128, 1, 255}));
  ASSERT_TRUE(cloud.has_intensities());
  EXPECT_FLOAT_EQ(cloud.intensities[0], 0.0f);
  EXPECT_FLOAT_EQ(cloud.intensities[1], 1.0f);
  EXPECT_FLOAT_EQ(cloud.intensities[2], 1023.0f / 2047.0f);
}

TEST(E57Reader, IntensityWithoutLimitsIsKeptAsStored) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan = cartesian_scan({{0, 0, 0}, {1, 0, 0}});
  scan.fields.push_back(test::e57_single("intensity", {0.25, 1234.5}));
  const PointCloud cloud = read_spec(dir, {{scan}, ""});
  ASSERT_TRUE(cloud.has_intensities());
  EXPECT_EQ(cloud.intensities, (std::vector<float>{0.25f, 1234.5f}));
}

TEST(E57Reader, InvalidStatesAreDroppedAndCounted) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan = cartesian_scan({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}});
  scan.fields.push_back(test::e57_integer("cartesianInvalidState", 0, 2, {0, 1, 2, 0, 0}));
  CloudReadReport report;
  const PointCloud cloud = read_spec(dir, {{scan}, ""}, &report);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.positions[0].x(), 0.0f);
  EXPECT_EQ(cloud.positions[1].x(), 3.0f);
  EXPECT_EQ(cloud.positions[2].x(), 4.0f);
  EXPECT_EQ(report.dropped_invalid, 2u);
  EXPECT_EQ(report.dropped_nan, 0u);
  EXPECT_EQ(cloud.station_ids.size(), 3u);
}

TEST(E57Reader, AllPointsInvalidIsNoPoints) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan = cartesian_scan({{0, 0, 0}, {1, 0, 0}});
  scan.fields.push_back(test::e57_integer("cartesianInvalidState", 0, 2, {2, 1}));
  testing::expect_input_error(
      [&] {
        read_spec(dir, {{scan}, ""});
      },
      "scan.e57", 0, "all 2 are marked invalid or direction-only");
}

TEST(E57Reader, EveryScanIsAStationAndTagsItsPoints) {
  const testing::ScratchDirectory dir;
  E57ScanSpec first = cartesian_scan({{0, 0, 0}, {1, 1, 1}});
  first.name = "Station 1";
  first.guid = "{guid-a}";
  first.translation = Eigen::Vector3d(1, 0, 0);
  E57ScanSpec second = cartesian_scan({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}});
  second.guid = "{guid-b}";
  second.translation = Eigen::Vector3d(0, 5, 0);
  E57ScanSpec third = cartesian_scan({{7, 7, 7}});
  const PointCloud cloud = read_spec(dir, {{first, second, third}, ""});
  ASSERT_EQ(cloud.stations.size(), 3u);
  EXPECT_EQ(cloud.stations[0].name, "Station 1");
  EXPECT_EQ(cloud.stations[1].name, "{guid-b}");
  EXPECT_EQ(cloud.stations[2].name, "scan_2");
  EXPECT_EQ(cloud.stations[0].frame.origin, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(cloud.stations[1].frame.origin, Eigen::Vector3d(0, 5, 0));
  EXPECT_EQ(cloud.station_ids, (std::vector<std::int32_t>{0, 0, 1, 1, 1, 2}));
  ASSERT_EQ(cloud.size(), 6u);
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(2, 1, 1));
  EXPECT_EQ(cloud.positions[4], Eigen::Vector3f(0, 7, 0));
  EXPECT_EQ(cloud.positions[5], Eigen::Vector3f(7, 7, 7));
  EXPECT_NO_THROW(cloud.validate());
}

TEST(E57Reader, GridFromIndexBoundsOrTheLargestIndex) {
  const testing::ScratchDirectory dir;
  E57ScanSpec bounded = cartesian_scan({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  bounded.fields.push_back(test::e57_integer("rowIndex", 0, 3, {0, 1, 2}));
  bounded.fields.push_back(test::e57_integer("columnIndex", 0, 4, {4, 0, 1}));
  bounded.extra_xml =
      "<indexBounds type=\"Structure\"><rowMinimum type=\"Integer\"/>"
      "<rowMaximum type=\"Integer\">3</rowMaximum><columnMinimum type=\"Integer\"/>"
      "<columnMaximum type=\"Integer\">4</columnMaximum></indexBounds>";
  E57ScanSpec unbounded = cartesian_scan({{1, 0, 0}, {0, 1, 0}});
  unbounded.fields.push_back(test::e57_integer("rowIndex", 0, 100, {2, 0}));
  unbounded.fields.push_back(test::e57_integer("columnIndex", 0, 100, {1, 6}));
  const PointCloud cloud = read_spec(dir, {{bounded, unbounded}, ""});
  ASSERT_EQ(cloud.stations.size(), 2u);
  EXPECT_EQ(cloud.stations[0].frame.width, 5u);
  EXPECT_EQ(cloud.stations[0].frame.height, 4u);
  EXPECT_EQ(cloud.stations[1].frame.width, 7u);
  EXPECT_EQ(cloud.stations[1].frame.height, 3u);
}

TEST(E57Reader, GeoreferencedScanIsShiftedAndSoAreItsStations) {
  const testing::ScratchDirectory dir;
  E57ScanSpec scan = cartesian_scan({{0.5, 0.25, 1}, {-3, 2, 0}});
  scan.translation = Eigen::Vector3d(500012.0, 5400034.0, 250.0);
  const PointCloud cloud = read_spec(dir, {{scan}, ""});
  ASSERT_TRUE(cloud.shifted());
  EXPECT_EQ(cloud.shift, Eigen::Vector3d(500000, 5400000, 300));
  EXPECT_EQ(cloud.original_position(0), Eigen::Vector3d(500012.5, 5400034.25, 251.0));
  EXPECT_EQ(cloud.original_position(1), Eigen::Vector3d(500009.0, 5400036.0, 250.0));
  EXPECT_EQ(cloud.stations[0].frame.origin, Eigen::Vector3d(12, 34, -50));
}

// The fuzz target's generated seed (tests/fuzz/corpus/e57/SOURCES.md).
TEST(E57Reader, FuzzSeedReads) {
  CloudReadReport report;
  const PointCloud cloud = read_cloud(
      std::string(OCCLUSION_SOURCE_DIR) + "/tests/fuzz/corpus/e57/two_scans.e57", {}, &report);
  EXPECT_EQ(cloud.size(), 8u);  // 6 - 2 invalid, then 4
  EXPECT_EQ(report.dropped_invalid, 2u);
  ASSERT_EQ(cloud.stations.size(), 2u);
  EXPECT_EQ(cloud.stations[0].name, "spherical");
  EXPECT_EQ(cloud.stations[0].frame.width, 2u);
  EXPECT_EQ(cloud.stations[0].frame.height, 3u);
  EXPECT_EQ(cloud.stations[1].name, "{seed-b}");
  EXPECT_EQ(cloud.station_ids, (std::vector<std::int32_t>{0, 0, 0, 0, 1, 1, 1, 1}));
  // Only the second scan has colours: the cloud keeps none.
  EXPECT_FALSE(cloud.has_colours());
  EXPECT_FALSE(cloud.has_intensities());
  expect_near(cloud.positions[4], {-3 - 10.0, 0.03, 0.5}, 1e-5);
}

// The fuzz seeds of bit widths (tests/fuzz/corpus/e57/SOURCES.md): fields of
// 32, 12, 1, 2 and 0 bits over 2 packets read; the same with X declared 1
// bit, or recordCount 4 of the 6 records written, are refused.
TEST(E57Reader, BitWidthFuzzSeeds) {
  const std::string seeds = std::string(OCCLUSION_SOURCE_DIR) + "/tests/fuzz/corpus/e57/";
  CloudReadReport report;
  const PointCloud cloud = read_cloud(seeds + "bit_widths.e57", {}, &report);
  ASSERT_EQ(cloud.size(), 5u);  // record 3 is invalid
  EXPECT_EQ(report.dropped_invalid, 1u);
  // Record 1: X (4e9 - 1000) * 1e-6 - 2000, Y 107 * 0.001, Z 1; intensity 5.
  const Eigen::Vector3d second = cloud.to_original(cloud.positions[1].cast<double>());
  EXPECT_NEAR(second.x(), 1999.999, 1e-3);
  EXPECT_NEAR(second.y(), 0.107, 1e-6);
  EXPECT_NEAR(second.z(), 1.0, 1e-6);
  ASSERT_TRUE(cloud.has_intensities());
  EXPECT_EQ(cloud.intensities[4], 5.0f);
  testing::expect_input_error([&] { read_cloud(seeds + "narrow_width.e57"); }, "narrow_width.e57",
                              0,
                              "holds 24 bytes of cartesianX, room for 192 records of its 1 bits");
  testing::expect_input_error([&] { read_cloud(seeds + "fewer_records.e57"); }, "fewer_records.e57",
                              0, "room for 6 records of its 32 bits, but recordCount is 4");
}

// --- errors ----------------------------------------------------------------

E57FileSpec many_points(std::size_t count) {
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < count; ++i) points.emplace_back(double(i), 0.5, -double(i));
  return {{cartesian_scan(points)}, ""};
}

TEST(E57Errors, AFlippedByteNamesItsPageAndOffset) {
  const testing::ScratchDirectory dir;
  std::string bytes = test::e57_bytes(many_points(200));  // ~5 kB: several pages
  ASSERT_GT(bytes.size(), 3u * 1024);
  bytes[2 * 1024 + 100] = static_cast<char>(bytes[2 * 1024 + 100] ^ 0x10);
  const std::string path = dir.file("flipped.e57");
  write_bytes(path, bytes);
  testing::expect_input_error([&] { read_cloud(path); }, "flipped.e57", 0,
                              "at byte 2048: page 2 (bytes 2048 to 3071) is corrupt");
}

TEST(E57Errors, ATruncatedFileSaysSo) {
  const testing::ScratchDirectory dir;
  const std::string bytes = test::e57_bytes(many_points(200));
  const std::string whole_pages = dir.file("pages.e57");
  write_bytes(whole_pages, bytes.substr(0, bytes.size() - 1024));
  testing::expect_input_error([&] { read_cloud(whole_pages); }, "pages.e57", 0, "(truncated)");
  const std::string mid_page = dir.file("mid.e57");
  write_bytes(mid_page, bytes.substr(0, 1500));
  testing::expect_input_error([&] { read_cloud(mid_page); }, "mid.e57", 0, "(truncated)");
  const std::string header = dir.file("header.e57");
  write_bytes(header, bytes.substr(0, 20));
  testing::expect_input_error([&] { read_cloud(header); }, "header.e57", 0,
                              "shorter than the 48-byte file header");
}

TEST(E57Errors, NotAnE57File) {
  const testing::ScratchDirectory dir;
  const std::string path = dir.file("points.e57");
  write_bytes(path, "1 2 3\n4 5 6\n");
  testing::expect_input_error([&] { read_cloud(path); }, "points.e57", 0,
                              "does not start with 'ASTM-E57'");
}

TEST(E57Errors, MoreRecordsThanTheSectionHolds) {
  const testing::ScratchDirectory dir;
  E57FileSpec spec = many_points(3);
  spec.scans[0].record_count = 1'000'000'000'000;
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "holds 24 bytes of cartesianX but its 1000000000000 records");
}

// A file whose X values are 32-bit integers in 0..4294967295, its XML then
// made to declare `range` (the same length, padded with spaces), so that the
// bytestream holds 32 bits a record where the prototype declares fewer.
std::string narrowed_bytes(const std::string& range) {
  E57FileSpec spec = many_points(100);
  std::vector<std::int64_t> raw;
  for (std::int64_t i = 0; i < 100; ++i) raw.push_back(4000000000 - 1000 * i);
  spec.scans[0].fields[0] = test::e57_integer("cartesianX", 0, 4294967295, raw);
  std::string bytes = test::e57_bytes(spec);
  const std::string declared = "minimum=\"0\" maximum=\"4294967295\"";
  const std::size_t at = bytes.find(declared);
  EXPECT_NE(at, std::string::npos);
  if (at == std::string::npos) return bytes;
  bytes.replace(at, declared.size(), range + std::string(declared.size() - range.size(), ' '));
  test::fix_e57_checksums(bytes);
  return bytes;
}

// Issue 44: read as 0 or 1 for every point, with no error.
TEST(E57Errors, ABitWidthNarrowerThanTheBytestreamIsRefused) {
  const testing::ScratchDirectory dir;
  const std::string path = dir.file("narrow.e57");
  write_bytes(path, narrowed_bytes("minimum=\"0\" maximum=\"4294967295\""));
  ASSERT_EQ(read_cloud(path).size(), 100u);  // as written, it reads
  write_bytes(path, narrowed_bytes("minimum=\"0\" maximum=\"1\""));
  testing::expect_input_error([&] { read_cloud(path); }, "narrow.e57", 0,
                              "holds 400 bytes of cartesianX, room for 3200 records of its 1 bits");
  write_bytes(path, narrowed_bytes("minimum=\"0\" maximum=\"0\""));
  testing::expect_input_error([&] { read_cloud(path); }, "narrow.e57", 0,
                              "cartesianX takes 0 bits a record");
}

// Issue 44: the first 40 points were read and the other 60 dropped silently.
TEST(E57Errors, FewerRecordsThanTheSectionHoldsAreRefused) {
  const testing::ScratchDirectory dir;
  E57FileSpec spec = many_points(100);
  spec.scans[0].record_count = 40;
  testing::expect_input_error(
      [&] { read_spec(dir, spec); }, "scan.e57", 0,
      "holds 800 bytes of cartesianX, room for 100 records of its 64 bits, but recordCount is 40");
  spec.scans[0].record_count = 99;
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "but recordCount is 99");
}

TEST(E57Errors, ACodecOtherThanBitPackIsRefused) {
  const testing::ScratchDirectory dir;
  E57FileSpec spec = many_points(3);
  spec.scans[0].codecs_xml =
      "<vectorChild type=\"Structure\"><inputs type=\"Vector\"/>"
      "<zLibCodec type=\"Structure\"/></vectorChild>";
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "data3D/0/points/codecs/0': uses the codec 'zLibCodec'");
}

TEST(E57Errors, ImagesOnlyIsRefused) {
  const testing::ScratchDirectory dir;
  E57FileSpec spec;
  spec.images2d_xml = "<vectorChild type=\"Structure\"></vectorChild>";
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "holds only images (1 in images2D)");
}

TEST(E57Errors, XmlErrorsNameTheElement) {
  const testing::ScratchDirectory dir;
  E57FileSpec spec = many_points(2);
  spec.scans[0].extra_xml =
      "<intensityLimits type=\"Structure\"><intensityMinimum type=\"Float\">abc"
      "</intensityMinimum></intensityLimits>";
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "'data3D/0/intensityLimits/intensityMinimum': value 'abc' is not a "
                              "number");
  spec.scans[0].extra_xml = "<broken";
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "E57 XML section, at character");
  spec.scans[0].extra_xml = "";
  spec.scans[0].rotation = Eigen::Quaterniond(2, 0, 0, 0);
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "'data3D/0/pose/rotation': is not a unit quaternion");
  spec.scans[0].rotation.reset();
  spec.scans[0].fields[1].name = "cartesianQ";
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "neither cartesianX/Y/Z nor sphericalRange/Azimuth/Elevation");
}

TEST(E57Errors, AStoredValueBeyondItsFieldsMaximum) {
  const testing::ScratchDirectory dir;
  E57FileSpec spec = many_points(4);
  // 0..2 takes 2 bits, which can also hold 3.
  spec.scans[0].fields.push_back(test::e57_integer("cartesianInvalidState", 0, 2, {0, 0, 3, 0}));
  testing::expect_input_error([&] { read_spec(dir, spec); }, "scan.e57", 0,
                              "record 2: cartesianInvalidState is outside its field's");
}

TEST(E57Errors, ScansSharingASectionAreRefused) {
  // Two scans whose XML points at the same bytes: a small file could
  // otherwise claim its points any number of times.
  const testing::ScratchDirectory dir;
  E57FileSpec spec = many_points(3);
  spec.scans.push_back(spec.scans[0]);
  std::string bytes = test::e57_bytes(spec);
  const std::string attribute = "fileOffset=\"";
  const std::size_t second = bytes.find(attribute, bytes.find(attribute) + 1) + attribute.size();
  const std::size_t quote = bytes.find('"', second);
  ASSERT_GE(quote - second, 2u);
  // fileOffset="NNN" becomes fileOffset="48" plus spaces: the XML keeps its length.
  bytes.replace(second, quote + 1 - second, "48\"" + std::string(quote - second - 2, ' '));
  test::fix_e57_checksums(bytes);
  const std::string path = dir.file("shared.e57");
  write_bytes(path, bytes);
  testing::expect_input_error([&] { read_cloud(path); }, "shared.e57", 0,
                              "data3D/1 ('scan_1'): its points' section overlaps that of data3D/0");
}

// The first section starts right after the 48-byte file header, its first
// data packet after the 32-byte section header: byte 80 of page 0.
std::string with_packet_bytes(const E57FileSpec& spec, std::size_t at, const std::string& values) {
  std::string bytes = test::e57_bytes(spec);
  bytes.replace(80 + at, values.size(), values);
  test::fix_e57_checksums(bytes);
  return bytes;
}

TEST(E57Errors, MalformedPacketsAreRefusedWithTheirOffset) {
  const testing::ScratchDirectory dir;
  const std::string path = dir.file("packet.e57");
  write_bytes(path, with_packet_bytes(many_points(3), 0, std::string("\x07", 1)));
  testing::expect_input_error([&] { read_cloud(path); }, "packet.e57", 0,
                              "at byte 80: data3D/0/points: unknown packet type 7");
  write_bytes(path, with_packet_bytes(many_points(3), 2, std::string("\x02\x00", 2)));
  testing::expect_input_error([&] { read_cloud(path); }, "packet.e57", 0,
                              "a data packet of 3 bytes is shorter than its 6-byte header");
  write_bytes(path, with_packet_bytes(many_points(3), 4, std::string("\x02\x00", 2)));
  testing::expect_input_error([&] { read_cloud(path); }, "packet.e57", 0,
                              "a data packet has 2 bytestreams but the prototype has 3 fields");
  write_bytes(path, with_packet_bytes(many_points(3), 2, std::string("\xff\xff", 2)));
  testing::expect_input_error([&] { read_cloud(path); }, "packet.e57", 0,
                              "a packet of 65536 bytes runs past the section's end");
}

}  // namespace
}  // namespace occlusion
