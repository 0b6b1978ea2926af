// CloudReadOptions::max_points: every reader stops at the first point beyond
// it, so a file too large for its use (plan's candidates, issue 44) is
// refused without being read whole.

#include <gtest/gtest.h>

#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

CloudReadOptions at_most(std::size_t points) {
  CloudReadOptions options;
  options.max_points = points;
  return options;
}

TEST(MaxPoints, AFileOfThatManyPointsIsReadAndOneMoreIsRefused) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("three.xyz");
  testing::write_text(path, "1 2 3\nnan 0 0\n4 5 6\n7 8 9\n");
  // The dropped point is not one of them.
  EXPECT_EQ(read_cloud(path, at_most(3)).size(), 3u);
  try {
    read_cloud(path, at_most(2));
    FAIL() << "three points read under a limit of two";
  } catch (const TooManyPoints& error) {
    EXPECT_EQ(error.max_points, 2u);
    EXPECT_NE(std::string(error.what()).find("more than 2 points"), std::string::npos)
        << error.what();
  }
}

// The reader stops at the point beyond the limit: a bad line after it is
// never reached.
TEST(MaxPoints, TheReaderStopsAtThePointBeyondTheLimit) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("long.txt");
  testing::write_text(path, "1 2 3\n4 5 6\n7 8 9\nnot a point\n");
  EXPECT_THROW(read_cloud(path, at_most(2)), TooManyPoints);
  testing::expect_input_error([&] { read_cloud(path); }, "long.txt", 4, "not a number");
}

// Every reader makes its points in one place, so binary files stop too.
TEST(MaxPoints, BinaryFilesStopToo) {
  testing::ScratchDirectory dir;
  const PointCloud cloud = testing::labelled_cloud();
  for (const char* name : {"c.ply", "c.pcd"}) {
    write_cloud(dir.file(name), cloud);
    EXPECT_EQ(read_cloud(dir.file(name), at_most(cloud.size())).size(), cloud.size()) << name;
    EXPECT_THROW(read_cloud(dir.file(name), at_most(cloud.size() - 1)), TooManyPoints) << name;
  }
}

}  // namespace
}  // namespace occlusion
