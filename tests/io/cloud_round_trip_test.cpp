#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

struct FormatCase {
  CloudFormat format;
  const char* extension;
  const char* name;
};

void PrintTo(const FormatCase& format_case, std::ostream* out) {
  *out << format_case.name;
}

class CloudRoundTrip : public ::testing::TestWithParam<FormatCase> {};

std::vector<ScalarField> extra_fields() {
  return {
      {"visibility", {0.25f, std::numeric_limits<float>::quiet_NaN(), 1.0f / 3.0f, -7.5f}, false},
      {"hits", {0, -3, 2147483520.0f, 17}, true}};
}

TEST_P(CloudRoundTrip, KeepsEveryAttributeExactly) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file(std::string("cloud") + GetParam().extension);
  const PointCloud cloud = testing::labelled_cloud();
  write_cloud(path, cloud, extra_fields(), GetParam().format);

  CloudReadReport report;
  const PointCloud back = read_cloud(path, {}, &report);
  ASSERT_EQ(back.size(), cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    // Bit-exact: binary formats store the float, ascii ones its shortest exact text.
    EXPECT_EQ(back.positions[i], cloud.positions[i]) << "point " << i;
  }
  EXPECT_EQ(back.colours, cloud.colours);
  EXPECT_EQ(back.labels, cloud.labels);
  EXPECT_EQ(back.instances, cloud.instances);
  EXPECT_EQ(back.class_names, cloud.class_names);
  EXPECT_EQ(report.dropped_nan, 0u);

  const std::vector<ScalarField> expected = extra_fields();
  ASSERT_EQ(report.extra_fields.size(), expected.size());
  for (std::size_t f = 0; f < expected.size(); ++f) {
    const ScalarField& got = report.extra_fields[f];
    EXPECT_EQ(got.name, expected[f].name);
    EXPECT_EQ(got.integer, expected[f].integer);
    ASSERT_EQ(got.values.size(), expected[f].values.size());
    for (std::size_t i = 0; i < got.values.size(); ++i) {
      if (std::isnan(expected[f].values[i])) {
        EXPECT_TRUE(std::isnan(got.values[i]));
      } else {
        EXPECT_EQ(got.values[i], expected[f].values[i]) << got.name << " " << i;
      }
    }
  }
}

TEST_P(CloudRoundTrip, PositionsOnlyStayPositionsOnly) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file(std::string("bare") + GetParam().extension);
  PointCloud cloud;
  cloud.positions = {{1, 2, 3}, {-4, 5.5f, 6e-3f}};
  write_cloud(path, cloud, {}, GetParam().format);
  CloudReadReport report;
  const PointCloud back = read_cloud(path, {}, &report);
  EXPECT_EQ(back.positions, cloud.positions);
  EXPECT_FALSE(back.has_colours());
  EXPECT_FALSE(back.has_labels());
  EXPECT_FALSE(back.has_instances());
  EXPECT_TRUE(back.class_names.empty());
  EXPECT_TRUE(report.extra_fields.empty());
}

std::string case_name(const ::testing::TestParamInfo<FormatCase>& info) {
  return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, CloudRoundTrip,
                         ::testing::Values(FormatCase{CloudFormat::kPcdBinaryCompressed, ".pcd",
                                                      "PcdBinaryCompressed"},
                                           FormatCase{CloudFormat::kPcdBinary, ".pcd", "PcdBinary"},
                                           FormatCase{CloudFormat::kPcdAscii, ".pcd", "PcdAscii"},
                                           FormatCase{CloudFormat::kPlyBinary, ".ply", "PlyBinary"},
                                           FormatCase{CloudFormat::kPlyAscii, ".ply", "PlyAscii"}),
                         case_name);

TEST(WriteCloud, FormatFollowsTheExtension) {
  testing::ScratchDirectory dir;
  const PointCloud cloud = testing::labelled_cloud();
  write_cloud(dir.file("a.pcd"), cloud);
  write_cloud(dir.file("b.PLY"), cloud);
  const std::string pcd = testing::read_bytes(dir.file("a.pcd"));
  const std::string ply = testing::read_bytes(dir.file("b.PLY"));
  EXPECT_NE(pcd.find("DATA binary_compressed\n"), std::string::npos);
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_EQ(read_cloud(dir.file("b.PLY")).labels, cloud.labels);
}

TEST(WriteCloud, PlyHeaderNamesClassesAndProperties) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("c.ply");
  write_cloud(path, testing::labelled_cloud(), extra_fields(), CloudFormat::kPlyAscii);
  const std::string text = testing::read_bytes(path);
  for (const char* line : {"comment class 0 ceiling\n", "comment class 1 floor with spaces\n",
                           "comment class 2 wall\n", "property uchar red\n",
                           "property int scalar_label\n", "property int scalar_instance\n",
                           "property float scalar_visibility\n", "property int scalar_hits\n"}) {
    EXPECT_NE(text.find(line), std::string::npos) << line;
  }
}

TEST(WriteCloud, PcdLabelIsUint32AsInPclPointTypes) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("l.pcd");
  write_cloud(path, testing::labelled_cloud(), {}, CloudFormat::kPcdAscii);
  const std::string text = testing::read_bytes(path);
  EXPECT_NE(text.find("FIELDS x y z rgb label instance\n"), std::string::npos) << text;
  EXPECT_NE(text.find("TYPE F F F U U I\n"), std::string::npos) << text;
  // Label -1 of the third point is stored as 0xFFFFFFFF.
  EXPECT_NE(text.find(" 4294967295 0\n"), std::string::npos) << text;
}

TEST(WriteCloud, RejectsMismatchedExtraFields) {
  testing::ScratchDirectory dir;
  const PointCloud cloud = testing::labelled_cloud();
  const std::string path = dir.file("x.ply");
  EXPECT_THROW(write_cloud(path, cloud, {{"short", {1, 2}, false}}), std::invalid_argument);
  EXPECT_THROW(write_cloud(path, cloud, {{"label", {1, 2, 3, 4}, true}}), std::invalid_argument);
  EXPECT_THROW(write_cloud(path, cloud, {{"two words", {1, 2, 3, 4}, false}}),
               std::invalid_argument);
  EXPECT_THROW(write_cloud(path, cloud, {{"a", {1, 2, 3, 4}, false}, {"a", {1, 2, 3, 4}, false}}),
               std::invalid_argument);
  EXPECT_THROW(write_cloud(path, cloud, {{"count", {1, 2.5f, 3, 4}, true}}), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty()) << "nothing is written when the arguments are wrong";
}

TEST(WriteCloud, RejectsUnknownOrContradictoryFormats) {
  testing::ScratchDirectory dir;
  const PointCloud cloud = testing::labelled_cloud();
  EXPECT_THROW(write_cloud(dir.file("x.xyz"), cloud), std::invalid_argument);
  EXPECT_THROW(write_cloud(dir.file("x.pcd"), cloud, {}, CloudFormat::kPlyAscii),
               std::invalid_argument);
  EXPECT_THROW(write_cloud(dir.file("x.ply"), cloud, {}, CloudFormat::kPcdBinary),
               std::invalid_argument);
  write_cloud(dir.file("x.bin"), cloud, {}, CloudFormat::kPlyBinary);
  EXPECT_EQ(testing::read_bytes(dir.file("x.bin")).rfind("ply\n", 0), 0u);
}

TEST(WriteCloud, RejectsInvalidCloud) {
  testing::ScratchDirectory dir;
  PointCloud cloud = testing::labelled_cloud();
  cloud.labels.pop_back();
  EXPECT_THROW(write_cloud(dir.file("x.ply"), cloud), std::invalid_argument);
  cloud = testing::labelled_cloud();
  cloud.positions[1].x() = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(write_cloud(dir.file("x.pcd"), cloud), std::invalid_argument);
}

TEST(WriteCloud, ReplacesAnExistingFileWhole) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("r.ply");
  testing::write_text(path, "old contents");
  write_cloud(path, testing::labelled_cloud());
  EXPECT_EQ(read_cloud(path).size(), 4u);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"r.ply"});
}

}  // namespace
}  // namespace occlusion
