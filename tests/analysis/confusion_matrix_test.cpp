#include "occlusion/analysis/confusion_matrix.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace occlusion {
namespace {

// The worked example of docs/metrics.md, in evaluation ids: wall 0, floor 1,
// chair 4, sofa 5 (no ground truth, never predicted), table 6 (no ground
// truth, predicted once); 255 is the ignore id, 7 a ground-truth id outside
// the classes, 9 a predicted id outside them, -1 a point without prediction.
constexpr std::int32_t kIgnore = 255;

ConfusionMatrix worked_example() {
  ConfusionMatrix m({{0, "wall"}, {1, "floor"}, {4, "chair"}, {5, "sofa"}, {6, "table"}});
  m.add({0, 0, 0, 0, 0, 0}, {0, 0, 0, 1, kIgnore, 9});  // wall: 3 right, 1 floor, 2 other
  m.add({1, 1, 1, 1, 1}, {1, 1, 1, 0, 6});              // floor: 3 right, 1 wall, 1 table
  m.add({4, 4, 4}, {4, -1, -1});                        // chair: 1 right, 2 unlabelled
  m.add({kIgnore, kIgnore, kIgnore, 7}, {0, 4, 1, 0});  // skipped, not false positives
  return m;
}

const ClassMetrics& find(const SegmentationMetrics& metrics, std::int32_t id) {
  for (const auto& c : metrics.classes) {
    if (c.id == id) return c;
  }
  throw std::logic_error("no class " + std::to_string(id));
}

TEST(ConfusionMatrix, CountsCellsOtherColumnAndSkipped) {
  const ConfusionMatrix m = worked_example();
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m.other_column(), 5u);
  const std::uint64_t expected[5][6] = {{3, 1, 0, 0, 0, 2},
                                        {1, 3, 0, 0, 1, 0},
                                        {0, 0, 1, 0, 0, 2},
                                        {0, 0, 0, 0, 0, 0},
                                        {0, 0, 0, 0, 0, 0}};
  for (std::size_t r = 0; r < 5; ++r) {
    for (std::size_t c = 0; c < 6; ++c) EXPECT_EQ(m.count(r, c), expected[r][c]) << r << "," << c;
  }
  EXPECT_EQ(m.total(), 14u);
  EXPECT_EQ(m.skipped(), 4u);
  EXPECT_EQ(m.index_of(4), 2u);
  EXPECT_FALSE(m.index_of(kIgnore));
  EXPECT_THROW(m.count(5, 0), std::out_of_range);
}

TEST(ConfusionMatrix, MetricsMatchHandComputedValues) {
  const SegmentationMetrics metrics = compute_metrics(worked_example());
  const ClassMetrics& wall = find(metrics, 0);
  EXPECT_EQ(wall.tp, 3u);
  EXPECT_EQ(wall.fp, 1u);
  EXPECT_EQ(wall.fn, 3u);  // the prediction of the ignore id and of id 9 are misses
  EXPECT_EQ(wall.support, 6u);
  EXPECT_DOUBLE_EQ(*wall.iou, 3.0 / 7.0);
  EXPECT_DOUBLE_EQ(*wall.precision, 0.75);
  EXPECT_DOUBLE_EQ(*wall.recall, 0.5);
  EXPECT_DOUBLE_EQ(*wall.f1, 0.6);

  const ClassMetrics& floor = find(metrics, 1);
  EXPECT_EQ(floor.fp, 1u);  // the skipped points predicted as floor are not counted
  EXPECT_DOUBLE_EQ(*floor.iou, 0.5);
  EXPECT_DOUBLE_EQ(*floor.precision, 0.75);
  EXPECT_DOUBLE_EQ(*floor.recall, 0.6);
  EXPECT_DOUBLE_EQ(*floor.f1, 2.0 / 3.0);

  const ClassMetrics& chair = find(metrics, 4);
  EXPECT_EQ(chair.fp, 0u);  // a skipped point predicted as chair is no false positive
  EXPECT_DOUBLE_EQ(*chair.iou, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(*chair.precision, 1.0);
  EXPECT_DOUBLE_EQ(*chair.recall, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(*chair.f1, 0.5);

  // Absent from both: no figure at all, rather than 0 or 1.
  const ClassMetrics& sofa = find(metrics, 5);
  EXPECT_EQ(sofa.support, 0u);
  EXPECT_FALSE(sofa.iou);
  EXPECT_FALSE(sofa.precision);
  EXPECT_FALSE(sofa.recall);
  EXPECT_FALSE(sofa.f1);

  // Predicted but absent from the ground truth: IoU 0, kept out of the mean.
  const ClassMetrics& table = find(metrics, 6);
  EXPECT_EQ(table.fp, 1u);
  EXPECT_DOUBLE_EQ(*table.iou, 0.0);
  EXPECT_DOUBLE_EQ(*table.precision, 0.0);
  EXPECT_FALSE(table.recall);
  EXPECT_DOUBLE_EQ(*table.f1, 0.0);

  EXPECT_EQ(metrics.classes_with_support, 3u);
  EXPECT_DOUBLE_EQ(*metrics.miou, 53.0 / 126.0);  // (3/7 + 1/2 + 1/3) / 3
  EXPECT_DOUBLE_EQ(*metrics.overall_accuracy, 0.5);
  EXPECT_DOUBLE_EQ(*metrics.mean_class_accuracy, 43.0 / 90.0);  // (1/2 + 3/5 + 1/3) / 3
  EXPECT_EQ(metrics.points, 14u);
  EXPECT_EQ(metrics.correct, 7u);
  EXPECT_EQ(metrics.other, 4u);
  EXPECT_EQ(metrics.skipped, 4u);
}

// The three averaging rules on the worked example: wall 3/7, floor 1/2 and
// chair 1/3 have ground truth; table (IoU 0, no recall) was only predicted;
// sofa has neither. Per-class figures do not change with the rule.
TEST(ConfusionMatrix, MeanOverRulesMatchHandComputedValues) {
  const ConfusionMatrix m = worked_example();
  const SegmentationMetrics support = compute_metrics(m, MeanOver::support);
  EXPECT_EQ(support.classes_averaged, 3u);
  EXPECT_DOUBLE_EQ(*support.miou, 53.0 / 126.0);
  EXPECT_DOUBLE_EQ(*support.mean_class_accuracy, 43.0 / 90.0);

  // ScanNet: table's 0 joins the mean, sofa's 0/0 (NaN there) does not.
  const SegmentationMetrics scannet = compute_metrics(m, MeanOver::scannet);
  EXPECT_EQ(scannet.mean_over, MeanOver::scannet);
  EXPECT_EQ(scannet.classes_averaged, 4u);
  EXPECT_DOUBLE_EQ(*scannet.miou, 53.0 / 168.0);  // (3/7 + 1/2 + 1/3 + 0) / 4
  EXPECT_DOUBLE_EQ(*scannet.mean_class_accuracy, 43.0 / 120.0);

  // Pointcept: all five classes, sofa and table at 0.
  const SegmentationMetrics pointcept = compute_metrics(m, MeanOver::pointcept);
  EXPECT_EQ(pointcept.classes_averaged, 5u);
  EXPECT_DOUBLE_EQ(*pointcept.miou, 53.0 / 210.0);
  EXPECT_DOUBLE_EQ(*pointcept.mean_class_accuracy, 43.0 / 150.0);

  // Each class says whether its rule took it (by id: wall, floor, chair, sofa, table).
  const auto averaged = [](const SegmentationMetrics& metrics) {
    std::vector<bool> flags;
    for (const auto& c : metrics.classes) flags.push_back(c.averaged);
    return flags;
  };
  EXPECT_EQ(averaged(support), (std::vector<bool>{true, true, true, false, false}));
  EXPECT_EQ(averaged(scannet), (std::vector<bool>{true, true, true, false, true}));
  EXPECT_EQ(averaged(pointcept), (std::vector<bool>{true, true, true, true, true}));

  for (const auto* metrics : {&scannet, &pointcept}) {
    EXPECT_DOUBLE_EQ(*metrics->overall_accuracy, 0.5);
    EXPECT_EQ(metrics->classes_with_support, 3u);
    ASSERT_EQ(metrics->classes.size(), support.classes.size());
    for (std::size_t c = 0; c < support.classes.size(); ++c) {
      EXPECT_EQ(metrics->classes[c].iou, support.classes[c].iou);
    }
  }
}

// A scene where every class has ground truth: the rules agree.
TEST(ConfusionMatrix, MeanOverRulesAgreeWhenEveryClassOccurs) {
  ConfusionMatrix m({{0, "wall"}, {1, "floor"}});
  m.add({0, 0, 1, 1}, {0, 1, 1, 1});  // wall 1/2, floor 2/3
  for (const MeanOver rule : {MeanOver::support, MeanOver::scannet, MeanOver::pointcept}) {
    EXPECT_DOUBLE_EQ(*compute_metrics(m, rule).miou, (1.0 / 2.0 + 2.0 / 3.0) / 2.0)
        << to_string(rule);
  }
}

TEST(ConfusionMatrix, MeanOverNamesRoundTrip) {
  for (const MeanOver rule : {MeanOver::support, MeanOver::scannet, MeanOver::pointcept}) {
    EXPECT_EQ(parse_mean_over(to_string(rule)), rule);
  }
  EXPECT_FALSE(parse_mean_over("ScanNet"));
  EXPECT_FALSE(parse_mean_over(""));
}

TEST(ConfusionMatrix, ScenesAreSummedNotAveraged) {
  const std::vector<EvaluationClass> classes = {{0, "wall"}, {1, "floor"}};
  ConfusionMatrix a(classes);
  a.add({0, 0}, {0, 0});
  ConfusionMatrix b(classes);
  b.add({0, 0, 1, 1}, {1, 1, 1, 1});
  b.add(kIgnore, 0, 5);
  EXPECT_DOUBLE_EQ(*compute_metrics(a).miou, 1.0);   // floor has no IoU there
  EXPECT_DOUBLE_EQ(*compute_metrics(b).miou, 0.25);  // wall 0, floor 2/4

  const ConfusionMatrix sum = a + b;
  EXPECT_EQ(sum.count(0, 0), 2u);
  EXPECT_EQ(sum.count(0, 1), 2u);
  EXPECT_EQ(sum.count(1, 1), 2u);
  EXPECT_EQ(sum.skipped(), 5u);
  // wall 2/4, floor 2/4: not the mean of the scenes' 1 and 0.25.
  EXPECT_DOUBLE_EQ(*compute_metrics(sum).miou, 0.5);
}

TEST(ConfusionMatrix, NoCountedPointsLeavesMeansUndefined) {
  ConfusionMatrix m({{0, "wall"}});
  m.add(kIgnore, 0);
  const SegmentationMetrics metrics = compute_metrics(m);
  EXPECT_FALSE(metrics.miou);
  EXPECT_FALSE(metrics.overall_accuracy);
  EXPECT_FALSE(metrics.mean_class_accuracy);
  EXPECT_EQ(metrics.skipped, 1u);
}

TEST(ConfusionMatrix, RejectsBadClassesAndMismatchedInputs) {
  EXPECT_THROW(ConfusionMatrix({{0, "a"}, {0, "b"}}), std::invalid_argument);
  EXPECT_THROW(ConfusionMatrix({{-1, "a"}}), std::invalid_argument);
  ConfusionMatrix m({{0, "wall"}});
  EXPECT_THROW(m.add(std::vector<std::int32_t>{0, 0}, std::vector<std::int32_t>{0}),
               std::invalid_argument);
  EXPECT_THROW(m += ConfusionMatrix({{0, "floor"}}), std::invalid_argument);
  // Classes are kept by id whatever order they are given in.
  const ConfusionMatrix sorted({{7, "door"}, {0, "wall"}});
  EXPECT_EQ(sorted.classes()[0].id, 0);
  EXPECT_EQ(sorted.classes()[1].id, 7);
}

}  // namespace
}  // namespace occlusion
