// class_names files: line k names label k; what could shift or contradict the
// names is refused with its line.

#include <gtest/gtest.h>

#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/class_names_file.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

TEST(ClassNamesFile, LineKNamesLabelK) {
  EXPECT_EQ(parse_class_names("\xEF\xBB\xBF"
                              "ceiling\r\n  shower curtain \r\nwall\n\n\n",
                              "n.txt"),
            (std::vector<std::string>{"ceiling", "shower curtain", "wall"}));
  EXPECT_EQ(parse_class_names("a\rb", "n.txt"), (std::vector<std::string>{"a", "b"}));
}

TEST(ClassNamesFile, WhatWouldShiftOrRepeatNamesIsRefused) {
  testing::expect_input_error([] { parse_class_names("floor\n\nwall\n", "n.txt"); }, "n.txt", 2,
                              "blank line");
  testing::expect_input_error([] { parse_class_names("floor\nwall\nfloor\n", "n.txt"); }, "n.txt",
                              3, "'floor' is named twice (first on line 1)");
  testing::expect_input_error([] { parse_class_names(" \n\n", "n.txt"); }, "n.txt", 0,
                              "no class names");
}

TEST(ClassNamesFile, NamesACloudsBareLabels) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("names.txt"), "ground\nbuilding\ntree\n");
  PointCloud cloud;
  cloud.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  cloud.labels = {2, -1, 0};
  apply_class_names_file(cloud, "c.ply", dir.file("names.txt"));
  EXPECT_EQ(cloud.class_names, (std::vector<std::string>{"ground", "building", "tree"}));
  cloud.validate();
  // The same names again are fine; other names contradict the cloud's.
  apply_class_names_file(cloud, "c.ply", dir.file("names.txt"));
  testing::write_text(dir.file("other.txt"), "ground\nroof\ntree\n");
  testing::expect_input_error(
      [&] { apply_class_names_file(cloud, "c.ply", dir.file("other.txt")); }, "c.ply", 0,
      "differ from the class_names file");
}

TEST(ClassNamesFile, ALabelWithoutANameOrACloudWithoutLabelsIsRefused) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("names.txt"), "ground\nbuilding\n");
  PointCloud cloud;
  cloud.positions = {{0, 0, 0}, {1, 0, 0}};
  cloud.labels = {0, 5};
  testing::expect_input_error(
      [&] { apply_class_names_file(cloud, "c.ply", dir.file("names.txt")); }, "names.txt", 0,
      "names labels 0..1, but c.ply has label 5");
  cloud.labels.clear();
  testing::expect_input_error(
      [&] { apply_class_names_file(cloud, "c.ply", dir.file("names.txt")); }, "c.ply", 0,
      "has no labels");
}

}  // namespace
}  // namespace occlusion
