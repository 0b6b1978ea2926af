// A ScanNet-layout scene scored with the built-in scannet20 mapping gives what
// ScanNet's BenchmarkScripts/3d_evaluation/evaluate_semantic_label.py gives: the
// confusion matrix and per-class IoUs below are worked out by hand from that
// script's rules (ground truth outside VALID_CLASS_IDS skipped; a prediction
// outside them counted as UNKNOWN, a false negative of its row and a false
// positive of no class; fp summed over valid rows only).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "support/scannet_scene.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;

// 16 vertices with NYU40 ground truth and a benchmark-format prediction (one
// NYU40 id per line):
//   wall (1)          x4: 1 1 2 0    2 right, 1 floor, 1 unknown (0 is no valid id)
//   floor (2)         x3: 2 2 1      2 right, 1 wall
//   chair (5)         x3: 5 13 7     1 right, 1 unknown (blinds is not scored), 1 table
//   refridgerator (24) x2: 24 3      1 right, 1 cabinet
//   ceiling (22)      x2: 1 5        skipped (not a valid class): no false positive
//   unannotated (0)   x2: 2 24       skipped
const std::vector<std::uint16_t> kTruth = {1, 1, 1, 1, 2, 2, 2, 5, 5, 5, 24, 24, 22, 22, 0, 0};
const char* const kPrediction = "1\n1\n2\n0\n2\n2\n1\n5\n13\n7\n24\n3\n1\n5\n2\n24\n";

fs::path write_scene(const fs::path& dir) {
  testing::ScanNetScene scene;
  for (std::size_t i = 0; i < kTruth.size(); ++i) {
    scene.positions.emplace_back(static_cast<float>(i % 4), static_cast<float>(i / 4), 0.0f);
    scene.colours.push_back({static_cast<std::uint8_t>(i), 100, 200});
    scene.labels.push_back(kTruth[i]);
  }
  scene.faces = {{0, 1, 4}, {1, 5, 4}};
  return testing::write_scannet_scene(dir, "scene0011_00", scene);
}

const ClassMetrics& metrics_of(const SegmentationMetrics& metrics, std::int32_t id) {
  for (const auto& c : metrics.classes) {
    if (c.id == id) return c;
  }
  throw std::logic_error("no class " + std::to_string(id));
}

TEST(ScanNetEvaluation, Scannet20GivesTheBenchmarkScriptsFigures) {
  testing::ScratchDirectory dir;
  const fs::path scene = write_scene(dir.path());
  testing::write_text(dir.file("scene0011_00.txt"), kPrediction);
  EvaluateRequest request;
  request.ground_truth = {scene.string()};
  request.predictions = {dir.file("scene0011_00.txt")};
  request.class_mapping = "scannet20";
  request.mean_over = MeanOver::scannet;
  const EvaluateReport report = run_evaluate(request);

  // The 20 benchmark classes, by NYU40 id, named as the benchmark prints them.
  ASSERT_EQ(report.confusion.size(), 20u);
  EXPECT_EQ(report.confusion.classes().front().id, 1);
  EXPECT_EQ(report.confusion.classes().back().id, 39);
  EXPECT_EQ(report.confusion.classes()[14].name, "refrigerator");

  const ConfusionMatrix& m = report.confusion;
  const auto cell = [&](std::int32_t truth, std::int32_t predicted) {
    return m.count(*m.index_of(truth), predicted < 0 ? m.other_column() : *m.index_of(predicted));
  };
  EXPECT_EQ(cell(1, 1), 2u);
  EXPECT_EQ(cell(1, 2), 1u);
  EXPECT_EQ(cell(1, -1), 1u);  // the script's UNKNOWN column
  EXPECT_EQ(cell(2, 2), 2u);
  EXPECT_EQ(cell(2, 1), 1u);
  EXPECT_EQ(cell(5, 5), 1u);
  EXPECT_EQ(cell(5, -1), 1u);
  EXPECT_EQ(cell(5, 7), 1u);
  EXPECT_EQ(cell(24, 24), 1u);
  EXPECT_EQ(cell(24, 3), 1u);
  EXPECT_EQ(m.total(), 12u);
  EXPECT_EQ(m.skipped(), 4u);  // ceiling and unannotated

  // get_iou: tp / (tp + fp + fn).
  const SegmentationMetrics& s = report.metrics;
  EXPECT_DOUBLE_EQ(*metrics_of(s, 1).iou, 2.0 / 5.0);   // wall: tp 2, fp 1, fn 2
  EXPECT_DOUBLE_EQ(*metrics_of(s, 2).iou, 2.0 / 4.0);   // floor: tp 2, fp 1, fn 1
  EXPECT_DOUBLE_EQ(*metrics_of(s, 5).iou, 1.0 / 3.0);   // chair: tp 1, fp 0, fn 2
  EXPECT_DOUBLE_EQ(*metrics_of(s, 24).iou, 1.0 / 2.0);  // refrigerator: tp 1, fn 1
  EXPECT_DOUBLE_EQ(*metrics_of(s, 7).iou, 0.0);         // table: fp 1 only
  EXPECT_DOUBLE_EQ(*metrics_of(s, 3).iou, 0.0);         // cabinet: fp 1 only
  EXPECT_EQ(metrics_of(s, 1).fp, 1u);  // the ceiling point predicted wall is no false positive
  EXPECT_FALSE(metrics_of(s, 4).iou.has_value());  // bed: 0/0, the script's nan
  EXPECT_EQ(s.classes_averaged, 6u);
  EXPECT_DOUBLE_EQ(*s.miou, (2.0 / 5 + 2.0 / 4 + 1.0 / 3 + 1.0 / 2) / 6);  // 13/45
  EXPECT_DOUBLE_EQ(*s.overall_accuracy, 6.0 / 12.0);
}

// ScanNet's script scores its 20 classes from a labels file without being
// told: so does -eval by default (class_mapping auto), and says why.
TEST(ScanNetEvaluation, ByDefaultANyu40GroundTruthIsScoredAsScanNetScoresIt) {
  testing::ScratchDirectory dir;
  const fs::path scene = write_scene(dir.path());
  testing::write_text(dir.file("pred.txt"), kPrediction);
  EvaluateRequest request;
  request.ground_truth = {(scene / "scene0011_00_vh_clean_2.labels.ply").string()};
  request.predictions = {dir.file("pred.txt")};
  ASSERT_EQ(request.class_mapping, ClassMapping::kByGroundTruth);
  const EvaluateReport chosen = run_evaluate(request);
  EXPECT_EQ(chosen.class_mapping, "scannet20");
  EXPECT_NE(chosen.class_mapping_reason.find("NYU40"), std::string::npos)
      << chosen.class_mapping_reason;
  const Json::Value json = to_json(chosen);
  EXPECT_EQ(json["mapping"]["builtin"].asString(), "scannet20");
  EXPECT_EQ(json["mapping"]["requested"].asString(), "auto");
  EXPECT_EQ(json["mapping"]["chosen_because"].asString(), chosen.class_mapping_reason);

  request.class_mapping = "scannet20";
  const EvaluateReport named = run_evaluate(request);
  EXPECT_TRUE(named.class_mapping_reason.empty());
  EXPECT_TRUE(to_json(named)["mapping"]["chosen_because"].isNull());
  EXPECT_EQ(chosen.confusion.size(), named.confusion.size());
  for (std::size_t r = 0; r < named.confusion.size(); ++r) {
    for (std::size_t c = 0; c <= named.confusion.size(); ++c) {
      EXPECT_EQ(chosen.confusion.count(r, c), named.confusion.count(r, c));
    }
  }
  EXPECT_EQ(chosen.metrics.miou, named.metrics.miou);
}

TEST(ScanNetEvaluation, AnS3disGroundTruthStaysWithTheSeedTable) {
  testing::ScratchDirectory dir;
  PointCloud cloud;
  cloud.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  cloud.labels = {0, 1, 1};
  cloud.class_names = {"wall", "floor"};
  write_cloud(dir.file("room.ply"), cloud);
  testing::write_text(dir.file("pred.txt"), "0\n1\n1\n");
  EvaluateRequest request;
  request.ground_truth = {dir.file("room.ply")};
  request.predictions = {dir.file("pred.txt")};
  const EvaluateReport report = run_evaluate(request);
  EXPECT_EQ(report.class_mapping, "table3.1");
  EXPECT_TRUE(report.class_mapping_reason.empty());
  EXPECT_DOUBLE_EQ(*report.metrics.miou, 1.0);
}

TEST(ScanNetEvaluation, TheSeedTableNamedSaysToUseScannet20) {
  testing::ScratchDirectory dir;
  const fs::path scene = write_scene(dir.path());
  testing::write_text(dir.file("pred.txt"), kPrediction);
  EvaluateRequest request;
  request.ground_truth = {scene.string()};
  request.predictions = {dir.file("pred.txt")};
  request.class_mapping = "table3.1";
  try {
    run_evaluate(request);
    ADD_FAILURE() << "table 3.1 cannot map NYU40 classes";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("class_mapping scannet20"), std::string::npos) << e.what();
  }
}

TEST(ScanNetEvaluation, TheSeedTableRefusesNyu40EvenWhenItKnowsEveryName) {
  testing::ScratchDirectory dir;
  testing::ScanNetScene scene;
  scene.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  scene.colours.assign(3, {1, 2, 3});
  scene.labels = {1, 2, 2};  // wall and floor: names table 3.1 has too, with other ids
  scene.faces = {{0, 1, 2}};
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0012_00", scene);
  testing::write_text(dir.file("pred.txt"), "1\n2\n2\n");
  EvaluateRequest request;
  request.ground_truth = {folder.string()};
  request.predictions = {dir.file("pred.txt")};
  request.class_mapping = "table3.1";
  EXPECT_THROW(run_evaluate(request), UsageError);
  request.class_mapping = "scannet20";
  EXPECT_DOUBLE_EQ(*run_evaluate(request).metrics.miou, 1.0);
}

TEST(ScanNetEvaluation, AMappingFileWithoutClassesNarrowsScannet20) {
  testing::ScratchDirectory dir;
  const fs::path scene = write_scene(dir.path());
  testing::write_text(dir.file("pred.txt"), kPrediction);
  testing::write_text(dir.file("narrow.json"), "{\"ignored_classes\": [\"refridgerator\"]}");
  EvaluateRequest request;
  request.ground_truth = {scene.string()};
  request.predictions = {dir.file("pred.txt")};
  request.class_mapping = "scannet20";
  request.mapping_path = dir.file("narrow.json");
  const EvaluateReport report = run_evaluate(request);
  EXPECT_EQ(report.confusion.size(), 19u);
  EXPECT_EQ(report.confusion.skipped(), 6u);  // the two refrigerator points too

  testing::write_text(dir.file("own.json"), "{\"classes\": {\"wall\": 1}}");
  request.mapping_path = dir.file("own.json");
  EXPECT_THROW(run_evaluate(request), KeyError);
}

}  // namespace
}  // namespace occlusion
