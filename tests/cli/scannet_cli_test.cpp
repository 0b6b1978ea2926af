// ScanNet scenes, class_names files and the scannet20 mapping on the command line.

#include <gtest/gtest.h>
#include <json/reader.h>

#include <sstream>
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

  const CliRun seed = run_cli("-eval '" + scene + "' --prediction '" + dir.file("pred.txt") +
                              "' --class-mapping table3.1 -q");
  EXPECT_EQ(seed.exit_code, 2);
  EXPECT_NE(seed.err.find("class_mapping scannet20"), std::string::npos) << seed.err;
  EXPECT_EQ(run_cli("-eval '" + scene + "' --prediction '" + dir.file("pred.txt") +
                    "' --class-mapping scannet200 -q")
                .exit_code,
            2);
}

// Issue 41: a labels file and a prediction, and nothing else, are scored as
// ScanNet's script scores them, and the report says so (text and JSON).
TEST(ScanNetCli, EvalOfALabelsFileChoosesScannet20AndSaysSo) {
  const TempDir dir;
  const std::string labels =
      (testing::write_scannet_scene(dir.path(), "scene0102_00", two_classes()) /
       "scene0102_00_vh_clean_2.labels.ply")
          .string();
  dir.write("pred.txt", "2\n2\n1\n2\n1\n1\n0\n1\n");
  const std::string args = "-eval '" + labels + "' --prediction '" + dir.file("pred.txt") + "'";
  const Json::Value json = run_json(args);
  EXPECT_EQ(json["mapping"]["builtin"].asString(), "scannet20");
  EXPECT_EQ(json["mapping"]["requested"].asString(), "auto");
  EXPECT_NE(json["mapping"]["chosen_because"].asString().find("ScanNet"), std::string::npos);
  EXPECT_EQ(json["mapping"]["evaluation_classes"].size(), 20u);
  EXPECT_DOUBLE_EQ(json["miou"].asDouble(),
                   run_json(args + " --class-mapping scannet20")["miou"].asDouble());
  const CliRun text = run_cli(args + " -q");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("class mapping scannet20 (20 evaluation classes): "), std::string::npos)
      << text.out;
}

// A prediction of 0 (no ScanNet class) on unannotated points costs nothing:
// no warning that it counts as a miss. On an annotated point it is one.
TEST(ScanNetCli, ForeignIdsAreWarnedOfOnlyWhereTheyCount) {
  const TempDir dir;
  const std::string scene =
      testing::write_scannet_scene(dir.path(), "scene0103_00", two_classes()).string();
  // Vertex 7 is unannotated (0): predicted 0 there, right everywhere else.
  dir.write("on_unannotated.txt", "2\n2\n2\n2\n1\n1\n1\n0\n");
  const CliRun quiet = run_cli("-eval '" + scene + "' --prediction '" +
                               dir.file("on_unannotated.txt") + "' --json -q");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err.find("no evaluation class"), std::string::npos) << quiet.err;
  const Json::Value json = testing::parse_json(quiet.out);
  EXPECT_EQ(json["warnings"].size(), 0u);
  EXPECT_EQ(json["scenes"][0]["foreign_prediction_ids"].size(), 0u);
  EXPECT_DOUBLE_EQ(json["miou"].asDouble(), 1.0);

  dir.write("on_a_wall.txt", "2\n2\n2\n2\n0\n1\n1\n0\n");
  const CliRun warned =
      run_cli("-eval '" + scene + "' --prediction '" + dir.file("on_a_wall.txt") + "' -q");
  ASSERT_EQ(warned.exit_code, 0) << warned.err;
  EXPECT_NE(warned.err.find("predicted ids 0 are no evaluation class"), std::string::npos)
      << warned.err;
}

// A class with no ground-truth point is shown as having none, not as an IoU
// of 0.0000 that reads as a score, and the default mean leaves it out.
TEST(ScanNetCli, AClassWithoutGroundTruthIsShownAsHavingNone) {
  const TempDir dir;
  const std::string scene =
      testing::write_scannet_scene(dir.path(), "scene0104_00", two_classes()).string();
  // One floor point predicted cabinet (3), which the scene does not hold.
  dir.write("pred.txt", "2\n2\n2\n3\n1\n1\n1\n0\n");
  const std::string args = "-eval '" + scene + "' --prediction '" + dir.file("pred.txt") + "'";
  const Json::Value json = run_json(args);
  const Json::Value* cabinet = nullptr;
  for (const auto& c : json["classes"]) {
    if (c["id"].asInt() == 3) cabinet = &c;
  }
  ASSERT_NE(cabinet, nullptr);
  EXPECT_EQ((*cabinet)["support"].asUInt64(), 0u);
  EXPECT_EQ((*cabinet)["fp"].asUInt64(), 1u);
  EXPECT_FALSE((*cabinet)["averaged"].asBool());
  EXPECT_EQ(json["classes_averaged"].asUInt64(), 2u);
  EXPECT_DOUBLE_EQ(json["miou"].asDouble(), (3.0 / 4 + 1.0) / 2);  // floor, wall

  const CliRun text = run_cli(args + " -q");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  std::string cabinet_row;
  std::istringstream lines(text.out);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(" cabinet ") != std::string::npos) cabinet_row = line;
  }
  EXPECT_NE(cabinet_row.find("no gt"), std::string::npos) << text.out;
  // Its precision, 0 of 1 predicted point right, is the only 0.0000 in the row.
  ASSERT_NE(cabinet_row.find("0.0000"), std::string::npos) << cabinet_row;
  EXPECT_EQ(cabinet_row.find("0.0000"), cabinet_row.rfind("0.0000")) << cabinet_row;
  // 18 of scannet20's classes: all but floor and wall, cabinet among them.
  EXPECT_NE(text.out.find("no gt: 18 classes have no ground-truth point."), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("leaves it out of the means"), std::string::npos) << text.out;

  // The Markdown table says the same.
  ASSERT_EQ(run_cli(args + " -q --out '" + dir.file("out") + "'").exit_code, 0);
  const std::string markdown = testing::read_text(dir.file("out/scene0104_00.eval.md"));
  EXPECT_NE(markdown.find("| 3 | cabinet | 0 | no gt | 0.0000 | – | no gt |"), std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("Class mapping: scannet20 ("), std::string::npos) << markdown;
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
