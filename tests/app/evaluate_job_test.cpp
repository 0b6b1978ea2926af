#include "occlusion/app/evaluate_job.hpp"

#include <gtest/gtest.h>
#include <json/reader.h>

#include <fstream>
#include <sstream>

#include "io/scratch_directory.hpp"
#include "occlusion/app/class_mapping_file.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/label_file.hpp"

namespace occlusion {
namespace {

// Ground truth on a line, one point per metre; the last floor point lies far
// from every predicted point.
SceneInput line_scene() {
  SceneInput scene;
  scene.ground_truth_name = "line.ply";
  scene.prediction_name = "line_pred.ply";
  PointCloud& truth = scene.ground_truth;
  truth.class_names = {"wall", "floor", "chair", "stairs"};
  truth.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {10, 0, 0}, {5, 0, 0}};
  truth.labels = {0, 0, 1, 2, 2, 1, 3};
  // A voxelised prediction, in evaluation ids of table 3.1: the second wall
  // point is called floor (1), the second chair clutter (25).
  scene.prediction.positions = {{0.01f, 0, 0}, {1.02f, 0, 0}, {2, 0, 0},
                                {3, 0.01f, 0}, {4, 0, 0},     {5, 0, 0}};
  scene.prediction.labels = {0, 1, 1, 4, 25, 4};
  return scene;
}

const ClassMetrics& find(const SegmentationMetrics& metrics, std::int32_t id) {
  for (const auto& c : metrics.classes) {
    if (c.id == id) return c;
  }
  throw std::logic_error("no class " + std::to_string(id));
}

TEST(EvaluateScene, TransfersByNearestNeighbourAndCountsFarPointsAsMisses) {
  const ClassMapping mapping = ClassMapping::seed_table().with_ignored({"stairs"});
  const SceneEvaluation scene = evaluate_scene(line_scene(), mapping, 0.05, 2);
  EXPECT_EQ(scene.transfer, "nearest_neighbour");
  EXPECT_EQ(scene.name, "line");
  EXPECT_EQ(scene.points, 7u);
  EXPECT_EQ(scene.prediction_points, 6u);
  EXPECT_EQ(scene.beyond_distance, 1u);
  EXPECT_EQ(scene.unlabelled, 1u);
  EXPECT_NEAR(scene.max_matched_distance, 0.02, 1e-6);
  EXPECT_TRUE(scene.foreign_predictions.empty());

  const SegmentationMetrics& m = scene.metrics;
  EXPECT_EQ(m.points, 6u);  // the stairs point is skipped
  EXPECT_EQ(m.skipped, 1u);
  EXPECT_EQ(m.other, 1u);                        // the far floor point
  EXPECT_DOUBLE_EQ(*find(m, 0).iou, 0.5);        // wall: tp 1, fn 1
  EXPECT_DOUBLE_EQ(*find(m, 1).iou, 1.0 / 3.0);  // floor: tp 1, fp 1, fn 1 (the far point)
  EXPECT_DOUBLE_EQ(*find(m, 4).iou, 0.5);        // chair: tp 1, fn 1
  EXPECT_DOUBLE_EQ(*find(m, 25).iou, 0.0);       // clutter: fp 1, no support
  EXPECT_DOUBLE_EQ(*m.miou, 4.0 / 9.0);          // (1/2 + 1/3 + 1/2) / 3
  EXPECT_DOUBLE_EQ(*m.overall_accuracy, 0.5);
}

TEST(EvaluateScene, DirectWhenThePointsAreTheGroundTruths) {
  const ClassMapping mapping = ClassMapping::seed_table().with_ignored({"stairs"});
  SceneInput scene = line_scene();
  scene.prediction.positions.clear();  // a label file
  scene.prediction.labels = {0, 0, 1, 4, 4, 1, 99};
  SceneEvaluation result = evaluate_scene(scene, mapping, 0.0, 1);
  EXPECT_EQ(result.transfer, "direct");
  EXPECT_DOUBLE_EQ(*result.metrics.miou, 1.0);
  // 99 sits on the stairs point, which is skipped: it costs nothing, so it is
  // not listed (the warning made of the list says such ids count as misses).
  EXPECT_TRUE(result.foreign_predictions.empty());

  scene.prediction.positions = scene.ground_truth.positions;  // a cloud on the same points
  scene.prediction.labels = {0, 0, 1, 4, 2, 1, 255};
  result = evaluate_scene(scene, mapping, 0.0, 1);
  EXPECT_EQ(result.transfer, "direct");
  EXPECT_DOUBLE_EQ(*result.metrics.miou, (1.0 + 1.0 + 0.5) / 3.0);        // chair: 2 is a miss
  EXPECT_EQ(result.foreign_predictions, (std::vector<std::int32_t>{2}));  // not the ignore id

  scene.prediction.positions.clear();
  scene.prediction.labels = {0, 0};
  EXPECT_THROW(evaluate_scene(scene, mapping, 0.05, 1), InputError);
}

TEST(EvaluateScene, NamedPredictionsAreMappedByName) {
  const ClassMapping mapping = ClassMapping::seed_table().with_ignored({"stairs"});
  SceneInput scene = line_scene();
  scene.prediction.positions = scene.ground_truth.positions;
  scene.prediction.labels = scene.ground_truth.labels;
  scene.prediction.class_names = scene.ground_truth.class_names;
  EXPECT_DOUBLE_EQ(*evaluate_scene(scene, mapping, 0.05, 1).metrics.miou, 1.0);
}

TEST(EvaluateScene, Errors) {
  const ClassMapping mapping = ClassMapping::seed_table();
  SceneInput scene = line_scene();
  try {
    evaluate_scene(scene, mapping, 0.05, 1);  // stairs is not in table 3.1
    FAIL() << "expected a UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("line.ply: classes not in the class mapping: stairs"),
              std::string::npos)
        << e.what();
  }
  const ClassMapping ignoring = mapping.with_ignored({"stairs"});
  EXPECT_THROW(evaluate_scene(scene, ignoring, 0.0, 1), UsageError);  // other points, no transfer
  scene.ground_truth.class_names.clear();
  scene.ground_truth.labels = {0, 0, 0, 0, 0, 0, 0};
  EXPECT_THROW(evaluate_scene(scene, ignoring, 0.05, 1), InputError);
  scene.ground_truth.labels.clear();
  EXPECT_THROW(evaluate_scene(scene, ignoring, 0.05, 1), InputError);
}

Json::Value parse(const std::string& text) {
  Json::Value value;
  Json::CharReaderBuilder builder;
  std::string errors;
  std::istringstream in(text);
  EXPECT_TRUE(Json::parseFromStream(builder, in, &value, &errors)) << errors;
  return value;
}

// The averaging rules through the job, on files: wall 1/2, floor 1/3 and
// chair 1/3 have ground truth; clutter (id 25) is predicted once but absent;
// table 3.1 has 12 evaluation classes.
TEST(EvaluateJob, MeanOverIsAppliedAndReported) {
  const testing::ScratchDirectory dir;
  PointCloud truth;
  truth.class_names = {"wall", "floor", "chair"};
  truth.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {5, 0, 0}};
  truth.labels = {0, 0, 1, 2, 2, 1};
  write_cloud(dir.file("room.ply"), truth);
  write_label_file(dir.file("room.labels"), {0, 1, 1, 4, 25, 4});
  EvaluateRequest request;
  request.ground_truth = {dir.file("room.ply")};
  request.predictions = {dir.file("room.labels")};
  const std::pair<MeanOver, double> cases[] = {{MeanOver::support, 7.0 / 18.0},
                                               {MeanOver::scannet, 7.0 / 24.0},
                                               {MeanOver::pointcept, 7.0 / 72.0}};
  for (const auto& [rule, miou] : cases) {
    request.mean_over = rule;
    const EvaluateReport report = run_evaluate(request);
    EXPECT_DOUBLE_EQ(*report.metrics.miou, miou) << to_string(rule);
    EXPECT_DOUBLE_EQ(*report.scenes.at(0).metrics.miou, miou) << to_string(rule);
    const Json::Value json = to_json(report);
    EXPECT_EQ(json["mean_over"].asString(), to_string(rule));
    EXPECT_EQ(json["parameters"]["mean_over"].asString(), to_string(rule));
    EXPECT_DOUBLE_EQ(json["miou"].asDouble(), miou);
  }
}

// Issue 44, 2.6: the reader dropped the prediction's NaN point, the rest were
// the ground truth's points, and the prediction scored as paired.
TEST(EvaluateJob, APredictionWithANonFinitePointIsRefusedWhenPairedByPosition) {
  const testing::ScratchDirectory dir;
  PointCloud truth;
  truth.class_names = {"wall", "floor"};
  truth.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  truth.labels = {0, 0, 1};
  write_cloud(dir.file("room.ply"), truth);
  // x y z label, in table 3.1's evaluation ids: the ground truth and one more.
  std::ofstream(dir.file("room_pred.txt")) << "0 0 0 0\n1 0 0 0\n2 0 0 1\nnan nan nan 0\n";
  EvaluateRequest request;
  request.ground_truth = {dir.file("room.ply")};
  request.predictions = {dir.file("room_pred.txt")};
  request.max_distance = 0.0;
  try {
    run_evaluate(request);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1 points with a non-finite coordinate"),
              std::string::npos)
        << e.what();
  }
  // Transferred by nearest neighbour, the point is left out, and said so.
  request.max_distance = 0.05;
  const EvaluateReport report = run_evaluate(request);
  EXPECT_DOUBLE_EQ(*report.metrics.miou, 1.0);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("non-finite"), std::string::npos) << report.warnings[0];
}

TEST(ClassMappingFile, DefaultsToTable3_1) {
  const ClassMapping narrowed =
      parse_class_mapping(parse(R"({"ignored_classes": ["beam", "column"]})"), "m.json");
  EXPECT_EQ(narrowed.evaluation_classes().size(), 10u);
  EXPECT_EQ(narrowed.evaluation_classes()[1].name, "floor+ceiling");
  EXPECT_EQ(narrowed.find("column"), 255);

  const ClassMapping own = parse_class_mapping(
      parse(R"({"classes": {"wall": 0, "floor": 1, "ceiling": 1}, "names": {"1": "ground"},
                "ignore": -100})"),
      "m.json");
  ASSERT_EQ(own.evaluation_classes().size(), 2u);
  EXPECT_EQ(own.evaluation_classes()[1].name, "ground");
  EXPECT_EQ(own.ignore_id(), -100);
  EXPECT_FALSE(own.find("chair"));
}

TEST(ClassMappingFile, ErrorsNameTheFileAndKey) {
  const auto expect_error = [](const std::string& text, const std::string& message) {
    try {
      parse_class_mapping(parse(text), "m.json");
      ADD_FAILURE() << "expected a UsageError for " << text;
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("m.json: ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  expect_error(R"({"clases": {}})", "unknown key 'clases'");
  expect_error(R"({"classes": {"wall": "0"}})", "'classes.wall' must be an integer");
  expect_error(R"({"classes": {"wall": 1.5}})", "'classes.wall' must be an integer");
  expect_error(R"({"names": {"one": "x"}})", "'names' keys are evaluation ids");
  expect_error(R"({"names": {"3": "x"}})", "no class maps to");
  expect_error(R"({"ignore": 0})", "has the ignore id 0");
  expect_error(R"({"ignored_classes": "beam"})", "'ignored_classes' must be a list");
  expect_error(R"([1, 2])", "a class mapping is a JSON object");
  EXPECT_THROW(load_class_mapping("/nonexistent/mapping.json"), UsageError);
}

}  // namespace
}  // namespace occlusion
