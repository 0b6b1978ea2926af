#include "occlusion/io/polygon_file.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"

namespace occlusion {
namespace {

using Polygons = std::vector<std::vector<Eigen::Vector3d>>;

TEST(PolygonFile, RoundTripIsExact) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("openings.txt");
  const Polygons polygons{{{0.1, 1.0 / 3.0, 2}, {1e-9, -4, 5}, {6, 7, 8.000000000000002}},
                          {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  write_polygons(path, polygons);
  EXPECT_EQ(read_polygons(path), polygons);
}

TEST(PolygonFile, CommentsBlankRunsAndCrlf) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("o.txt");
  testing::write_text(path,
                      "# window\r\n0 0 0\r\n1 0 0  # first edge\r\n# still the window\r\n"
                      "1 1 0\r\n\r\n \t\r\n\r\n# door\r\n5 5 5\r\n6 5 5\r\n6 6 5");
  const Polygons polygons = read_polygons(path);
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons[0].size(), 3u);
  EXPECT_EQ(polygons[1][2], Eigen::Vector3d(6, 6, 5));
}

TEST(PolygonFile, ErrorsNameTheLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bad.txt");
  testing::write_text(path, "0 0 0\n1 0 0\n1 one 0\n");
  testing::expect_input_error([&] { read_polygons(path); }, "bad.txt", 3, "'one'");
  testing::write_text(path, "0 0 0\n1 0 0\n1 1\n");
  testing::expect_input_error([&] { read_polygons(path); }, "bad.txt", 3, "needs 3 coordinates");
  testing::write_text(path, "0 0 0\n1 0 0\n1 1 0 1\n");
  testing::expect_input_error([&] { read_polygons(path); }, "bad.txt", 3, "has more");
  testing::write_text(path, "0 0 0\n1 0 nan\n1 1 0\n");
  testing::expect_input_error([&] { read_polygons(path); }, "bad.txt", 2, "not a finite number");
}

TEST(PolygonFile, PolygonWithTooFewPointsNamesItsLastLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("two.txt");
  testing::write_text(path, "0 0 0\n1 0 0\n1 1 0\n\n5 5 5\n6 5 5\n\n");
  testing::expect_input_error([&] { read_polygons(path); }, "two.txt", 6,
                              "polygon has 2 points, needs at least 3");
}

TEST(PolygonFile, EmptyFileIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("empty.txt");
  testing::write_text(path, "# no openings yet\n\n");
  testing::expect_input_error([&] { read_polygons(path); }, "empty.txt", 0, "no polygons");
}

TEST(PolygonFile, WriterRejectsWhatTheReaderWould) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("w.txt");
  EXPECT_THROW(write_polygons(path, {}), std::invalid_argument);
  EXPECT_THROW(write_polygons(path, {{{0, 0, 0}, {1, 0, 0}}}), std::invalid_argument);
  EXPECT_THROW(write_polygons(path, {{{0, 0, 0}, {1, 0, 0}, {0, 1, 1.0 / 0.0}}}),
               std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace occlusion
