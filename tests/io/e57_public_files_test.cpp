// The E57 reader against public files written by other tools (files/e57,
// SOURCES.md there): their XML states the point counts and bounds asserted here.

#include <gtest/gtest.h>

#include <string>

#include "cloud_test_support.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

std::string sample(const std::string& name) {
  return std::string(OCCLUSION_SOURCE_DIR) + "/files/e57/" + name;
}

// The cloud's box, in the file's frame, equals `lo`..`hi` within `tolerance`.
void expect_bounds(const PointCloud& cloud, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                   double tolerance) {
  Eigen::Vector3f low, high;
  cloud.bounds(low, high);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(cloud.to_original(low.cast<double>())[axis], lo[axis], tolerance) << axis;
    EXPECT_NEAR(cloud.to_original(high.cast<double>())[axis], hi[axis], tolerance) << axis;
  }
}

TEST(E57PublicFiles, BunnyOfThirtyTwoBitScaledIntegers) {
  CloudReadReport report;
  const PointCloud cloud = read_cloud(sample("bunnyInt32.e57"), {}, &report);
  EXPECT_EQ(cloud.size() + report.dropped_invalid, 30571u);  // recordCount
  EXPECT_EQ(report.dropped_invalid, 0u);
  // cartesianBounds in the XML, and the scale (1e-6) the values are stored at.
  expect_bounds(cloud, {-0.094689, 0.040011, -0.061873}, {0.061009, 0.187321, 0.058799}, 1e-6);
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_EQ(cloud.stations[0].name, "bunny");
  EXPECT_FALSE(cloud.has_colours());
}

TEST(E57PublicFiles, ColouredCubeOfSingleFloats) {
  const PointCloud cloud = read_cloud(sample("ColouredCubeFloat.e57"));
  EXPECT_EQ(cloud.size(), 7680u);
  expect_bounds(cloud, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, 1e-6);
  ASSERT_TRUE(cloud.has_colours());
  ASSERT_EQ(cloud.stations.size(), 1u);
  // No name: the scan's guid names the station.
  EXPECT_EQ(cloud.stations[0].name, "Coloured Cube Float Scan Header GUID");
  // A cube coloured by position spans the whole 0..255 range on each channel.
  int lowest[3] = {255, 255, 255}, highest[3] = {0, 0, 0};
  for (const auto& rgb : cloud.colours) {
    for (int c = 0; c < 3; ++c) {
      lowest[c] = std::min(lowest[c], int{rgb[static_cast<std::size_t>(c)]});
      highest[c] = std::max(highest[c], int{rgb[static_cast<std::size_t>(c)]});
    }
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(lowest[c], 0) << c;
    EXPECT_EQ(highest[c], 255) << c;
  }
}

TEST(E57PublicFiles, Las2e57ScaledIntegersAndSixteenBitColours) {
  const PointCloud cloud = read_cloud(sample("ColourRepresentation.e57"));
  EXPECT_EQ(cloud.size(), 153u);
  expect_bounds(cloud, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, 1e-9);
  EXPECT_TRUE(cloud.has_colours());
}

TEST(E57PublicFiles, TranslationWithoutRotation) {
  const PointCloud cloud = read_cloud(sample("translationWithoutRotation.e57"));
  EXPECT_EQ(cloud.size(), 4u);
  // The XML's cartesianBounds (pye57 writes them in the file's frame).
  expect_bounds(cloud, {4, 5, 6}, {5, 6, 6}, 1e-9);
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_EQ(cloud.stations[0].name, "Scan 0");
  EXPECT_EQ(cloud.stations[0].frame.origin, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(cloud.stations[0].frame.orientation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
  // rowMaximum is given, but no point has a rowIndex: no grid.
  EXPECT_EQ(cloud.stations[0].frame.width, 0u);
}

TEST(E57PublicFiles, RefusedFilesSayWhy) {
  testing::expect_input_error([] { read_cloud(sample("bad-crc.e57")); }, "bad-crc.e57", 0,
                              "page 0 (bytes 0 to 1023) is corrupt: its CRC-32C checksum is "
                              "0x1392e413 but its bytes give 0x360e223d");
  testing::expect_input_error(
      [] { read_cloud(sample("PinholeImageWithDistortionParameters.e57")); },
      "PinholeImageWithDistortionParameters.e57", 0, "holds only images (3 in images2D)");
  testing::expect_input_error([] { read_cloud(sample("ZeroPoints.e57")); }, "ZeroPoints.e57", 0,
                              "no points");
}

}  // namespace
}  // namespace occlusion
