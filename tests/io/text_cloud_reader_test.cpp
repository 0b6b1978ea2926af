#include <gtest/gtest.h>

#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

TEST(TextCloudReader, ReadsEachColumnLayout) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("a.xyz"), "1 2 3\n4.5 -5e-1 +6\n");
  const PointCloud xyz = read_cloud(dir.file("a.xyz"));
  EXPECT_EQ(xyz.positions[1], Eigen::Vector3f(4.5f, -0.5f, 6.0f));
  EXPECT_FALSE(xyz.has_colours() || xyz.has_labels());

  testing::write_text(dir.file("b.txt"), "1 2 3 7\n4 5 6 3.000000\n");
  const PointCloud labelled = read_cloud(dir.file("b.txt"));
  EXPECT_EQ(labelled.labels, (std::vector<std::int32_t>{7, 3}));
  EXPECT_FALSE(labelled.has_colours());

  testing::write_text(dir.file("c.pts"), "1 2 3 255 0 9\n");
  const PointCloud coloured = read_cloud(dir.file("c.pts"));
  EXPECT_EQ(coloured.colours[0], (std::array<std::uint8_t, 3>{255, 0, 9}));
  EXPECT_FALSE(coloured.has_labels());

  testing::write_text(dir.file("d.TXT"), "1 2 3 10 20 30 -1\n");
  const PointCloud both = read_cloud(dir.file("d.TXT"));
  EXPECT_EQ(both.colours[0], (std::array<std::uint8_t, 3>{10, 20, 30}));
  EXPECT_EQ(both.labels, (std::vector<std::int32_t>{-1}));
}

TEST(TextCloudReader, SkipsCommentsBlankLinesAndCrlf) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("cc.txt");
  testing::write_text(path, "\xEF\xBB\xBF//X Y Z R G B\r\n# exported\r\n\r\n1 2 3 4 5 6\r\n  \r\n");
  const PointCloud cloud = read_cloud(path);
  ASSERT_EQ(cloud.size(), 1u);
  EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{4, 5, 6}));
}

// Lines ending in CR alone: read as one line, two points became one point
// with a colour.
TEST(TextCloudReader, ALoneCrEndsALine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("mac.txt");
  testing::write_text(path, "1 2 3\r4 5 6\r");
  const PointCloud cloud = read_cloud(path);
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_TRUE(cloud.colours.empty());
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(4, 5, 6));
}

TEST(TextCloudReader, NanAndInfinitePointsAreDroppedAndCounted) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("n.txt");
  testing::write_text(path, "1 2 3\nnan 0 0\n0 inf 0\n0 0 1e999\n4 5 6\n");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  EXPECT_EQ(cloud.size(), 2u);
  EXPECT_EQ(report.dropped_nan, 3u);
}

TEST(TextCloudReader, NonNumericTokenNamesTheLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bad.txt");
  testing::write_text(path, "# header\n1 2 3\n4 5 6\n7 8,5 9\n");
  testing::expect_input_error([&] { read_cloud(path); }, "bad.txt", 4, "'8,5' is not a number");
}

TEST(TextCloudReader, ColumnCountMustStayTheSame) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("mixed.txt");
  testing::write_text(path, "1 2 3 4 5 6\n1 2 3 4 5 6\n1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "mixed.txt", 3,
                              "3 columns, but line 1 has 6");
  testing::write_text(path, "1 2 3 4 5\n");
  testing::expect_input_error([&] { read_cloud(path); }, "mixed.txt", 1, "5 columns; expected");
  testing::write_text(path, "1 2 3 4 5 6 7 8 9\n");
  testing::expect_input_error([&] { read_cloud(path); }, "mixed.txt", 1, "more than 7 columns");
  // A Leica PTS point-count line is not a point.
  testing::write_text(path, "2\n1 2 3\n4 5 6\n");
  testing::expect_input_error([&] { read_cloud(path); }, "mixed.txt", 1, "1 columns; expected");
}

TEST(TextCloudReader, ColoursAndLabelsMustBeWholeNumbersInRange) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("rgb.txt");
  testing::write_text(path, "1 2 3 0.5 0.5 0.5\n");
  testing::expect_input_error([&] { read_cloud(path); }, "rgb.txt", 1, "colour '0.5'");
  testing::write_text(path, "1 2 3 10 20 300\n");
  testing::expect_input_error([&] { read_cloud(path); }, "rgb.txt", 1, "colour '300'");
  testing::write_text(path, "1 2 3 2.5\n");
  testing::expect_input_error([&] { read_cloud(path); }, "rgb.txt", 1, "label '2.5'");
  testing::write_text(path, "1 2 3 -4\n");
  testing::expect_input_error([&] { read_cloud(path); }, "rgb.txt", 1, "label -4 is negative");
}

TEST(TextCloudReader, SkipBadLinesCountsThem) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("skip.txt");
  testing::write_text(path, "1 2 x\n1 2 3 4 5 6\n7 8 9 1 2 3\n1 2 3\n4 5 6 7 8 9\n");
  CloudReadOptions options;
  options.skip_bad_lines = true;
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, options, &report);
  // The corrupt first line does not decide the layout; the first good one does.
  EXPECT_EQ(cloud.size(), 3u);
  EXPECT_TRUE(cloud.has_colours());
  EXPECT_EQ(report.skipped_lines, 2u);
}

TEST(TextCloudReader, FileWithNoPointsIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("empty.txt");
  testing::write_text(path, "# nothing here\n\n");
  testing::expect_input_error([&] { read_cloud(path); }, "empty.txt", 0, "no points");
}

TEST(ReadCloud, UnknownExtensionListsTheSupportedOnes) {
  testing::ScratchDirectory dir;
  // A FARO scanner's own format, which no reader here reads.
  const std::string path = dir.file("scan.fls");
  testing::write_text(path, "FARO");
  testing::expect_input_error([&] { read_cloud(path); }, "scan.fls", 0,
                              "supported: .pcd, .ply, .txt, .xyz, .pts");
  for (const char* suffix : {".las", ".frame.json"}) {
    testing::expect_input_error([&] { read_cloud(path); }, "scan.fls", 0, suffix);
  }
}

TEST(ReadCloud, MissingPathIsAnInputError) {
  testing::ScratchDirectory dir;
  testing::expect_input_error([&] { read_cloud(dir.file("nowhere.ply")); }, "nowhere.ply", 0,
                              "no such file");
}

}  // namespace
}  // namespace occlusion
