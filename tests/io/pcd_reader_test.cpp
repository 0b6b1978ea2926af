#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

const std::string kRoomScan = std::string(OCCLUSION_SOURCE_DIR) + "/files/pcl/room_scan1.pcd";

std::string pcd_header(const std::string& fields, const std::string& sizes,
                       const std::string& types, std::size_t width, std::size_t height,
                       const std::string& data) {
  std::string header = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n";
  header += "FIELDS " + fields + "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT ";
  std::size_t field_count = 1;
  for (const char c : fields) field_count += c == ' ';
  for (std::size_t f = 0; f < field_count; ++f) header += f == 0 ? "1" : " 1";
  header += "\nWIDTH " + std::to_string(width) + "\nHEIGHT " + std::to_string(height) +
            "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(width * height) + "\nDATA " +
            data + "\n";
  return header;
}

std::string floats(std::initializer_list<float> values) {
  std::string bytes(values.size() * 4, '\0');
  std::size_t at = 0;
  for (const float value : values) {
    std::memcpy(&bytes[at], &value, 4);
    at += 4;
  }
  return bytes;
}

TEST(PcdReader, RealBinaryCompressedScanLoads) {
  CloudReadReport report;
  const PointCloud cloud = read_cloud(kRoomScan, {}, &report);
  EXPECT_EQ(cloud.size(), 112586u);
  EXPECT_EQ(report.dropped_nan, 0u);
  EXPECT_FALSE(cloud.has_colours());
  EXPECT_FALSE(cloud.has_labels());
  Eigen::Vector3f lo;
  Eigen::Vector3f hi;
  cloud.bounds(lo, hi);
  ASSERT_TRUE(lo.allFinite() && hi.allFinite());
  const Eigen::Vector3f extent = hi - lo;
  EXPECT_NEAR(extent.x(), 29.2, 0.5);
  EXPECT_NEAR(extent.y(), 14.5, 0.5);
  EXPECT_NEAR(extent.z(), 3.06, 0.2);
}

TEST(PcdReader, TruncatedCompressedScanIsReportedWithByteOffsets) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("cut.pcd");
  const std::string bytes = testing::read_bytes(kRoomScan);
  ASSERT_GT(bytes.size(), 300000u);
  testing::write_text(path, bytes.substr(0, 300000));
  testing::expect_input_error([&] { read_cloud(path); }, "cut.pcd", 0, "file ends at byte 300000");
}

TEST(PcdReader, AsciiNanPointsAreDroppedAndCounted) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("kinect.pcd");
  // An organised 2 x 2 frame, as a Kinect writes it: missing depth is NaN.
  testing::write_text(path, pcd_header("x y z", "4 4 4", "F F F", 2, 2, "ascii") +
                                "1 2 3\nnan nan nan\n4 5 6\nnan nan nan\n");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(4, 5, 6));
  EXPECT_EQ(report.dropped_nan, 2u);
  // The kept points' pixels: (0, 0) and (0, 1), row by row.
  EXPECT_EQ(cloud.pixels, (std::vector<std::uint32_t>{0, 2}));
}

TEST(PcdReader, UnorganisedCloudsHaveNoPixels) {
  const PointCloud cloud = read_cloud(kRoomScan);
  EXPECT_FALSE(cloud.sensor.organised());
  EXPECT_FALSE(cloud.has_pixels());
}

TEST(PcdReader, AllNanIsNoPointsNotAnEmptyCloud) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("blind.pcd");
  testing::write_text(path, pcd_header("x y z", "4 4 4", "F F F", 1, 1, "ascii") + "nan nan nan\n");
  testing::expect_input_error([&] { read_cloud(path); }, "blind.pcd", 0, "no points");
}

TEST(PcdReader, BinaryWithNanAndSeparateColourChannels) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("rgb.pcd");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::string body = floats({1, 2, 3});
  body += std::string("\x0a\x14\x1e\x00", 4);  // r g b and a padding byte "_"
  body += floats({nan, 0, 0});
  body += std::string("\x01\x02\x03\x00", 4);
  body += floats({-1, -2, -3});
  body += std::string("\xff\x80\x00\x00", 4);
  testing::write_text(
      path, pcd_header("x y z r g b _", "4 4 4 1 1 1 1", "F F F U U U U", 3, 1, "binary") + body);
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_EQ(report.dropped_nan, 1u);
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(-1, -2, -3));
  EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{10, 20, 30}));
  EXPECT_EQ(cloud.colours[1], (std::array<std::uint8_t, 3>{255, 128, 0}));
  EXPECT_TRUE(report.extra_fields.empty()) << "padding is not a field";
}

// Binary bodies are read where they lie in the file: values of every size at
// unaligned offsets (15-byte points) read as the same cloud written in ascii.
TEST(PcdReader, BinaryOfOddPointSizeReadsAsItsAsciiTwin) {
  testing::ScratchDirectory dir;
  const std::string fields = "x y z _";
  const std::string sizes = "4 8 2 1";
  const std::string types = "F F I U";
  std::string body;
  std::string ascii;
  for (int i = 0; i < 1000; ++i) {
    const float x = 0.25f * static_cast<float>(i) - 7.5f;
    const double y = 0.5 * i - 100.0;
    const auto z = static_cast<std::int16_t>(300 - 7 * i);
    char point[15];
    std::memcpy(point, &x, 4);
    std::memcpy(point + 4, &y, 8);
    std::memcpy(point + 12, &z, 2);
    point[14] = static_cast<char>(i);
    body.append(point, 15);
    ascii += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " " +
             std::to_string(i % 256) + "\n";
  }
  const std::string binary_path = dir.file("odd.pcd");
  const std::string ascii_path = dir.file("odd_ascii.pcd");
  testing::write_text(binary_path, pcd_header(fields, sizes, types, 1000, 1, "binary") + body);
  testing::write_text(ascii_path, pcd_header(fields, sizes, types, 1000, 1, "ascii") + ascii);
  const PointCloud binary = read_cloud(binary_path);
  const PointCloud text = read_cloud(ascii_path);
  ASSERT_EQ(binary.size(), 1000u);
  ASSERT_EQ(text.size(), 1000u);
  for (std::size_t i = 0; i < binary.size(); ++i) {
    ASSERT_EQ(binary.positions[i], text.positions[i]) << "point " << i;
  }
  EXPECT_EQ(binary.positions[3], Eigen::Vector3f(-6.75f, -98.5f, 279.0f));
}

TEST(PcdReader, PclLabelTypeAndObjectFieldMapToLabelsAndInstances) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("xyzl.pcd");
  testing::write_text(path, pcd_header("x y z label object curvature", "4 4 4 4 4 4", "F F F U I F",
                                       2, 1, "ascii") +
                                "0 0 0 7 3 0.5\n1 1 1 4294967295 -1 0.25\n");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{7, -1}));
  EXPECT_EQ(cloud.instances, (std::vector<std::int32_t>{3, -1}));
  ASSERT_EQ(report.extra_fields.size(), 1u);
  EXPECT_EQ(report.extra_fields[0].name, "curvature");
  EXPECT_EQ(report.extra_fields[0].values, (std::vector<float>{0.5f, 0.25f}));
}

TEST(PcdReader, FloatColourChannelsAreAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("float_rgb.pcd");
  testing::write_text(path, pcd_header("x y z r g b", "4 4 4 4 4 4", "F F F F F F", 1, 1, "ascii") +
                                "0 0 0 0.5 0.5 0.5\n");
  testing::expect_input_error([&] { read_cloud(path); }, "float_rgb.pcd", 0, "floating point");
}

TEST(PcdReader, TruncatedBinaryGivesByteOffsets) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("short.pcd");
  const std::string header = pcd_header("x y z", "4 4 4", "F F F", 3, 1, "binary");
  testing::write_text(path, header + floats({1, 2, 3, 4, 5}));
  testing::expect_input_error([&] { read_cloud(path); }, "short.pcd", 0,
                              "the file ends at byte " + std::to_string(header.size() + 20));
}

TEST(PcdReader, BinaryLongerThanTheHeaderSaysIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("long.pcd");
  testing::write_text(
      path, pcd_header("x y z", "4 4 4", "F F F", 1, 1, "binary") + floats({1, 2, 3, 4, 5, 6}));
  testing::expect_input_error([&] { read_cloud(path); }, "long.pcd", 0, "12 bytes after");
}

TEST(PcdReader, AsciiErrorsNameTheLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bad.pcd");
  const std::string header = pcd_header("x y z", "4 4 4", "F F F", 3, 1, "ascii");  // 11 lines
  testing::write_text(path, header + "1 2 3\n4 x 6\n7 8 9\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.pcd", 13, "'x' is not a number");
  testing::write_text(path, header + "1 2 3\n4 5\n7 8 9\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.pcd", 13, "2 values");
  testing::write_text(path, header + "1 2 3\n4 5 6 7\n7 8 9\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.pcd", 13, "more than the 3");
  testing::write_text(path, header + "1 2 3\n4 5 6\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.pcd", 13,
                              "ends after 2 of the 3 points");
  testing::write_text(path, header + "1 2 3\n4 5 6\n7 8 9\n1 1 1\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.pcd", 15, "more data lines");
}

TEST(PcdReader, CorruptPointCountFailsBeforeAllocating) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("huge.pcd");
  // 4e9 points of 12 bytes: PCL alone would try to allocate 48 GB.
  testing::write_text(
      path, pcd_header("x y z", "4 4 4", "F F F", 4000000000, 1, "binary") + floats({1, 2, 3}));
  testing::expect_input_error([&] { read_cloud(path); }, "huge.pcd", 0,
                              "declares 4000000000 points");
}

TEST(PcdReader, NotAPcdFile) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("text.pcd");
  testing::write_text(path, "hello\nworld\n");
  testing::expect_input_error([&] { read_cloud(path); }, "text.pcd", 0, "no DATA line");
}

TEST(PcdReader, WrongHeaderCountIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("fields.pcd");
  testing::write_text(path, pcd_header("x y z", "4 4", "F F F", 1, 1, "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "fields.pcd", 0, "PCD header");
}

TEST(PcdReader, MissingCoordinateFieldIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("xy.pcd");
  testing::write_text(path, pcd_header("x y", "4 4", "F F", 1, 1, "ascii") + "1 2\n");
  testing::expect_input_error([&] { read_cloud(path); }, "xy.pcd", 0, "no 'z' field");
}

TEST(PcdReader, LabelWithoutAClassNameIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("named.pcd");
  std::string text = pcd_header("x y z label", "4 4 4 4", "F F F I", 2, 1, "ascii");
  text.insert(text.find('\n') + 1, "# class 0 floor\n# class 1 wall\n");
  testing::write_text(path, text + "0 0 0 1\n1 1 1 2\n");
  testing::expect_input_error([&] { read_cloud(path); }, "named.pcd", 15, "label 2 has no class");
}

}  // namespace
}  // namespace occlusion
