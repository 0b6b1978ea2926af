// Colours stored as floats in PLY clouds: 0..255 (averaged, as preprocessed
// ScanNet clouds hold them) or 0..1, told apart by the values, rounded to 0..255.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

std::string float_colour_ply(const std::string& type, const std::string& body, int points) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(points) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty " + type +
         " red\nproperty " + type + " green\nproperty " + type + " blue\nend_header\n" + body;
}

TEST(PlyFloatColours, AveragedZeroTo255AreRounded) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("averaged.ply");
  // 127.5 rounds half away from zero; 0.4 is below 1 but 254.6 says the scale is 0..255.
  testing::write_text(path,
                      float_colour_ply("float", "0 0 0 127.5 0.4 254.6\n1 0 0 1 2 3.49\n", 2));
  const PointCloud cloud = read_cloud(path);
  ASSERT_EQ(cloud.colours.size(), 2u);
  EXPECT_EQ(cloud.colours[0], (Rgb{128, 0, 255}));
  EXPECT_EQ(cloud.colours[1], (Rgb{1, 2, 3}));
}

TEST(PlyFloatColours, ZeroToOneAreScaled) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("unit.ply");
  // 0.5 x 255 = 127.5 -> 128; 1 -> 255; 0.2 x 255 = 51.
  testing::write_text(path, float_colour_ply("double", "0 0 0 0.5 1 0\n1 0 0 0.2 0 1\n", 2));
  const PointCloud cloud = read_cloud(path);
  ASSERT_EQ(cloud.colours.size(), 2u);
  EXPECT_EQ(cloud.colours[0], (Rgb{128, 255, 0}));
  EXPECT_EQ(cloud.colours[1], (Rgb{51, 0, 255}));
}

TEST(PlyFloatColours, BlackIsBlackOnEitherScale) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("black.ply");
  testing::write_text(path, float_colour_ply("float", "0 0 0 0 0 0\n", 1));
  EXPECT_EQ(read_cloud(path).colours[0], (Rgb{0, 0, 0}));
}

TEST(PlyFloatColours, OnlyZeroAndOneIsAmbiguousAndRefused) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("ambiguous.ply");
  testing::write_text(path, float_colour_ply("float", "0 0 0 1 0 1\n1 0 0 0 1 0\n", 2));
  testing::expect_input_error([&] { read_cloud(path); }, "ambiguous.ply", 0,
                              "fits both 0..1 and 0..255");
}

TEST(PlyFloatColours, OutOfRangeNamesTheLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bright.ply");
  testing::write_text(path, float_colour_ply("float", "0 0 0 1 2 3\n1 0 0 255.5 0 0\n", 2));
  // Header lines 1-10, the second point on line 12.
  testing::expect_input_error([&] { read_cloud(path); }, "bright.ply", 12, "outside 0..255");
  testing::write_text(path, float_colour_ply("float", "0 0 0 -0.5 0 0\n", 1));
  testing::expect_input_error([&] { read_cloud(path); }, "bright.ply", 11, "outside 0..255");
}

TEST(PlyFloatColours, BinaryFloatColoursOfAMeshAreRead) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("mesh.ply");
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nproperty float red\nproperty float green\n"
      "property float blue\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n";
  for (const float value : {1.0f, 2.0f, 3.0f, 10.25f, 200.75f, 99.5f}) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int shift = 0; shift < 32; shift += 8) bytes += static_cast<char>(bits >> shift);
  }
  testing::write_text(path, bytes);
  EXPECT_EQ(read_cloud(path).colours[0], (Rgb{10, 201, 100}));
}

}  // namespace
}  // namespace occlusion
