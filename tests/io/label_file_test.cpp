#include "occlusion/io/label_file.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"

namespace occlusion {
namespace {

using Labels = std::vector<std::int32_t>;

TEST(LabelFile, RoundTrip) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("scene.labels");
  const Labels labels = {0, 25, -1, 2147483647, 1};
  write_label_file(path, labels);
  EXPECT_EQ(read_label_file(path), labels);
  EXPECT_EQ(testing::read_bytes(path), "0\n25\n-1\n2147483647\n1\n");
}

TEST(LabelFile, NumpyStyleCommentsBlankLinesAndCrlf) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("pred.txt");
  testing::write_text(path, "\xEF\xBB\xBF# predictions\r\n3.000000e+00\r\n\r\n  +4 \r\n-1\r\n7");
  EXPECT_EQ(read_label_file(path), (Labels{3, 4, -1, 7}));
}

TEST(LabelFile, ErrorsNameTheLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bad.labels");
  const auto expect_error = [&](const std::string& text, std::size_t line,
                                const std::string& message) {
    testing::write_text(path, text);
    testing::expect_input_error([&] { read_label_file(path); }, "bad.labels", line, message);
  };
  expect_error("1\n2\n2.5\n", 3, "'2.5' is not a whole number");
  expect_error("1\n-2\n", 2, "out of range");
  expect_error("1\n4294967296\n", 2, "out of range");
  expect_error("1\n0.1 0.2 0.3 4\n", 2, "one number per line");
  expect_error("# nothing\n\n", 0, "no labels");
  testing::expect_input_error([&] { read_label_file(dir.file("missing.labels")); },
                              "missing.labels", 0, "cannot open");
}

TEST(LabelFile, TellsLabelFilesFromClouds) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("labels.txt"), "# header\n\n4\n5\n");
  testing::write_text(dir.file("cloud.txt"), "// CloudCompare\n0 0 0 4\n1 0 0 5\n");
  EXPECT_TRUE(is_label_file(dir.file("labels.txt")));
  EXPECT_FALSE(is_label_file(dir.file("cloud.txt")));
  EXPECT_TRUE(is_label_file(dir.file("any.labels")));  // by extension, unread
  EXPECT_TRUE(is_label_file(dir.file("any.LABEL")));
  EXPECT_FALSE(is_label_file(dir.file("room.ply")));
}

}  // namespace
}  // namespace occlusion
