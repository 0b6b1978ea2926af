// ScanNet scenes, class_names files and the scannet20 mapping on the command line.

#include <gtest/gtest.h>
#include <json/reader.h>

#include <string>

#include "run_cli.hpp"
#include "support/scannet_scene.hpp"

namespace occlusion {
namespace {

using testing::CliRun;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

// Two triangles on the floor (NYU40 2) and one on a wall (1), far apart, and
// an unannotated vertex (0) in no face.
testing::ScanNetScene two_classes() {
  testing::ScanNetScene scene;
  scene.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                     {3, 0, 0}, {3, 1, 0}, {3, 0, 1}, {9, 9, 9}};
  scene.colours.assign(scene.positions.size(), {90, 90, 90});
  scene.labels = {2, 2, 2, 2, 1, 1, 1, 0};
  scene.faces = {{0, 1, 2}, {1, 3, 2}, {4, 5, 6}};
  return scene;
}

TEST(ScanNetCli, EvalTakesTheSceneAndTheBuiltInMapping) {
  const TempDir dir;
  const std::string scene =
      testing::write_scannet_scene(dir.path(), "scene0100_00", two_classes()).string();
  dir.write("pred.txt", "2\n2\n1\n2\n1\n1\n0\n1\n");
  const Json::Value json = run_json("-eval '" + scene + "' --prediction '" + dir.file("pred.txt") +
                                    "' --class-mapping scannet20");
  EXPECT_EQ(json["mapping"]["builtin"].asString(), "scannet20");
  // floor: tp 3, fp 0, fn 1; wall: tp 2, fp 1, fn 1 (0 is a miss; the
  // unannotated point predicted wall is skipped) -> (3/4 + 2/4) / 2.
  EXPECT_DOUBLE_EQ(json["miou"].asDouble(), (3.0 / 4 + 2.0 / 4) / 2);

  const CliRun seed =
      run_cli("-eval '" + scene + "' --prediction '" + dir.file("pred.txt") + "' -q");
  EXPECT_EQ(seed.exit_code, 2);
  EXPECT_NE(seed.err.find("class_mapping scannet20"), std::string::npos) << seed.err;
  EXPECT_EQ(run_cli("-eval '" + scene + "' --prediction '" + dir.file("pred.txt") +
                    "' --class-mapping scannet200 -q")
                .exit_code,
            2);
}

TEST(ScanNetCli, MocMeasuresEachClassOfTheSceneMesh) {
  const TempDir dir;
  const std::string scene =
      testing::write_scannet_scene(dir.path(), "scene0101_00", two_classes()).string();
  const Json::Value json = run_json("-moc '" + scene + "' --viewpoint 0.3,0.3,2");
  ASSERT_EQ(json["groups"].size(), 2u);
  EXPECT_EQ(json["groups"][0]["name"].asString(), "floor");
  EXPECT_EQ(json["groups"][1]["name"].asString(), "wall");
  EXPECT_EQ(json["degenerate_faces_skipped"].asUInt64(), 0u);
}

TEST(ScanNetCli, ClassNamesFileNamesATextCloudsLabels) {
  const TempDir dir;
  dir.write("cloud.txt", "0 0 0 1\n1 0 0 1\n0 1 0 0\n5 5 5 2\n");
  dir.write("names.txt", "ground\nbuilding\ntree\n");
  const Json::Value json =
      run_json("-fscan '" + dir.file("cloud.txt") +
               "' --viewpoint 0.3,0.3,1 --primitive sphere --point-radius 0.01 --class-names '" +
               dir.file("names.txt") + "'");
  ASSERT_EQ(json["classes"].size(), 3u);
  EXPECT_EQ(json["classes"][0]["name"].asString(), "ground");
  EXPECT_EQ(json["classes"][1]["points"].asUInt64(), 2u);
  EXPECT_EQ(json["classes"][2]["name"].asString(), "tree");

  dir.write("short.txt", "ground\n\nbuilding\n");
  const CliRun blank =
      run_cli("-fscan '" + dir.file("cloud.txt") +
              "' --viewpoint 0.3,0.3,1 --primitive sphere --point-radius 0.01 -q --class-names '" +
              dir.file("short.txt") + "'");
  EXPECT_EQ(blank.exit_code, 3);
  EXPECT_NE(blank.err.find("short.txt:2: blank line"), std::string::npos) << blank.err;
}

}  // namespace
}  // namespace occlusion
