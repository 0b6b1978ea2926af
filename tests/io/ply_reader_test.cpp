#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

// Big-endian bytes of a float, built by shifts so the test runs on any host.
std::string big_endian(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  std::string bytes;
  for (int shift = 24; shift >= 0; shift -= 8) bytes += static_cast<char>(bits >> shift);
  return bytes;
}

std::string little_endian(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  std::string bytes;
  for (int shift = 0; shift < 32; shift += 8) bytes += static_cast<char>(bits >> shift);
  return bytes;
}

TEST(PlyReader, AsciiWithFacesAndOtherToolsNames) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("mesh.ply");
  testing::write_text(path,
                      "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info x\r\n"
                      "element vertex 3\r\nproperty double x\r\nproperty double y\r\n"
                      "property double z\r\nproperty float nx\r\nproperty uchar red\r\n"
                      "property uchar green\r\nproperty uchar blue\r\nproperty uchar alpha\r\n"
                      "property ushort class\r\nproperty int object_id\r\n"
                      "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
                      "0.5 1.5 2.5 0.1 10 20 30 255 3 9\r\n"
                      "-1 -2 -3 0.2 40 50 60 255 4 8\r\n"
                      "\r\n"
                      "7 8 9 0.3 70 80 90 255 5 7\r\n"
                      "3 0 1 2\r\n");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(-1, -2, -3));
  EXPECT_EQ(cloud.colours[2], (std::array<std::uint8_t, 3>{70, 80, 90}));
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{3, 4, 5}));
  EXPECT_EQ(cloud.instances, (std::vector<std::int32_t>{9, 8, 7}));
  ASSERT_EQ(report.extra_fields.size(), 2u);
  EXPECT_EQ(report.extra_fields[0].name, "nx");
  EXPECT_FALSE(report.extra_fields[0].integer);
  EXPECT_EQ(report.extra_fields[1].name, "alpha");
  EXPECT_TRUE(report.extra_fields[1].integer);
}

TEST(PlyReader, BigEndianBinaryWithNanDropped) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("big.ply");
  std::string body;
  for (const float value : {1.0f, 2.0f, 3.0f, std::nanf(""), 0.0f, 0.0f, -4.0f, 5.5f, 1e-3f}) {
    body += big_endian(value);
  }
  testing::write_text(path,
                      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n" +
                          body);
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(-4.0f, 5.5f, 1e-3f));
  EXPECT_EQ(report.dropped_nan, 1u);
}

const std::string kBinaryHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 10\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n";

TEST(PlyReader, TruncatedBinaryGivesByteOffsets) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("cut.ply");
  std::string body;
  for (int i = 0; i < 14; ++i) body += little_endian(static_cast<float>(i));  // 4 2/3 vertices
  testing::write_text(path, kBinaryHeader + body);
  const std::size_t end = kBinaryHeader.size() + body.size();
  testing::expect_input_error(
      [&] { read_cloud(path); }, "cut.ply", 0,
      "the file ends at byte " + std::to_string(end) + ", after 4 of the 10 vertex records");
  testing::expect_input_error([&] { read_cloud(path); }, "cut.ply", 0,
                              "from byte " + std::to_string(kBinaryHeader.size()));
}

TEST(PlyReader, TruncatedListGivesByteOffsets) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("faces.ply");
  std::string body;
  for (int i = 0; i < 9; ++i) body += little_endian(static_cast<float>(i));
  body += std::string("\x03\x00\x00\x00\x00", 5);  // a triangle cut after its first index
  testing::write_text(path,
                      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 1\n"
                      "property list uchar int vertex_indices\nend_header\n" +
                          body);
  testing::expect_input_error([&] { read_cloud(path); }, "faces.ply", 0, "inside face 0 of the 1");
}

TEST(PlyReader, HeaderCountAboveTheDataIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("ten.ply");
  std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 10\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  for (int i = 0; i < 5; ++i) ascii += "1 2 3\n";
  testing::write_text(path, ascii);
  testing::expect_input_error([&] { read_cloud(path); }, "ten.ply", 12,
                              "ends after 5 of the 10 vertex lines");

  std::string binary = kBinaryHeader;
  for (int i = 0; i < 15; ++i) binary += little_endian(1.0f);
  testing::write_text(path, binary);
  testing::expect_input_error([&] { read_cloud(path); }, "ten.ply", 0,
                              "after 5 of the 10 vertex records");
}

TEST(PlyReader, HeaderCountBelowTheDataIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("two.ply");
  testing::write_text(path,
                      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n7 8 9\n");
  testing::expect_input_error([&] { read_cloud(path); }, "two.ply", 10, "data after the last");
  std::string binary = kBinaryHeader;
  for (int i = 0; i < 33; ++i) binary += little_endian(1.0f);
  testing::write_text(path, binary);
  testing::expect_input_error([&] { read_cloud(path); }, "two.ply", 0, "12 bytes after the end");
}

TEST(PlyReader, AsciiValueErrorsNameTheLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bad.ply");
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      "end_header\n";
  testing::write_text(path, header + "1 2 3 4 5 6\n1 2 three 4 5 6\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.ply", 12, "'three' is not a number");
  testing::write_text(path, header + "1 2 3 4 5 6\n1 2 3 4 5 256\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.ply", 12, "'256'");
  testing::write_text(path, header + "1 2 3 4 5 6\n1 2 3 4 5\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.ply", 12, "ends before");
  testing::write_text(path, header + "1 2 3 4 5 6 7\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.ply", 11, "more values");
}

TEST(PlyReader, HeaderErrorsNameTheLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("head.ply");
  testing::write_text(path, "plyx\nformat ascii 1.0\nend_header\n");
  testing::expect_input_error([&] { read_cloud(path); }, "head.ply", 1, "not a PLY file");
  testing::write_text(path, "ply\nformat ascii 1.0\nelement vertex 1\nproperty flot x\n");
  testing::expect_input_error([&] { read_cloud(path); }, "head.ply", 4, "unknown property type");
  testing::write_text(path,
                      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                      "property float y\nend_header\n1 2\n");
  testing::expect_input_error([&] { read_cloud(path); }, "head.ply", 3, "no scalar 'z'");
  testing::write_text(path,
                      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                      "property float y\nproperty float z\nproperty float red\n"
                      "property uchar green\nproperty float blue\nend_header\n1 2 3 0.1 2 0.3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "head.ply", 3,
                              "mixes integer and floating-point");
  testing::write_text(path, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
  testing::expect_input_error([&] { read_cloud(path); }, "head.ply", 0, "no end_header");
  testing::write_text(path,
                      "ply\nformat ascii 1.0\ncomment class 0 floor\ncomment class 0 wall\n"
                      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                      "end_header\n1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "head.ply", 4, "named twice");
}

TEST(PlyReader, ClassCommentsGiveNamesAndBoundLabels) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("named.ply");
  const std::string header =
      "ply\nformat ascii 1.0\ncomment class 1 wall\ncomment class 0 floor\n"
      "comment classes follow the S3DIS order\nelement vertex 2\nproperty float x\n"
      "property float y\nproperty float z\nproperty int label\nend_header\n";
  testing::write_text(path, header + "0 0 0 1\n1 1 1 0\n");
  const PointCloud cloud = read_cloud(path);
  EXPECT_EQ(cloud.class_names, (std::vector<std::string>{"floor", "wall"}));
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{1, 0}));
  testing::write_text(path, header + "0 0 0 1\n1 1 1 2\n");
  testing::expect_input_error([&] { read_cloud(path); }, "named.ply", 13, "label 2 has no class");
}

}  // namespace
}  // namespace occlusion
