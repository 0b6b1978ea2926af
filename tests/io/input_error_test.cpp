#include "occlusion/io/input_error.hpp"

#include <gtest/gtest.h>

namespace occlusion {
namespace {

TEST(InputError, MessageHasPathAndLine) {
  const InputError error("scan.pcd", 12, "bad field");
  EXPECT_STREQ(error.what(), "scan.pcd:12: bad field");
  EXPECT_EQ(error.path, "scan.pcd");
  EXPECT_EQ(error.line, 12u);
  EXPECT_EQ(error.reason, "bad field");
}

TEST(InputError, LineZeroMeansNoLine) {
  EXPECT_STREQ(InputError("a.obj", 0, "no faces").what(), "a.obj: no faces");
}

TEST(OutputError, MessageHasPath) {
  const OutputError error("out/x.ply", "disk full");
  EXPECT_STREQ(error.what(), "out/x.ply: disk full");
  EXPECT_EQ(error.path, "out/x.ply");
}

}  // namespace
}  // namespace occlusion
