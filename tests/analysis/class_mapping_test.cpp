#include "occlusion/analysis/class_mapping.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

TEST(ClassMapping, SeedTableIsTable3_1) {
  const ClassMapping mapping = ClassMapping::seed_table();
  const std::vector<std::pair<std::int32_t, std::string>> expected = {
      {0, "wall"},  {1, "floor+ceiling"}, {4, "chair"},    {5, "sofa"},
      {6, "table"}, {7, "door"},          {8, "window"},   {9, "bookcase"},
      {20, "beam"}, {21, "board"},        {25, "clutter"}, {26, "column"}};
  ASSERT_EQ(mapping.evaluation_classes().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(mapping.evaluation_classes()[i].id, expected[i].first);
    EXPECT_EQ(mapping.evaluation_classes()[i].name, expected[i].second);
  }
  EXPECT_EQ(mapping.find("ceiling"), 1);
  EXPECT_EQ(mapping.find("floor"), 1);
  EXPECT_FALSE(mapping.find("stairs"));
  EXPECT_EQ(mapping.ignore_id(), 255);
  // Every S3DIS class is mapped.
  EXPECT_TRUE(
      mapping.unmapped_classes({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}, s3dis_class_names())
          .empty());
}

TEST(ClassMapping, MapsLabelsByNameAndSkipsIgnoredClasses) {
  const ClassMapping mapping = ClassMapping::seed_table().with_ignored({"beam", "stairs"});
  EXPECT_EQ(mapping.evaluation_classes().size(), 11u);  // beam's id 20 is gone
  EXPECT_EQ(mapping.find("beam"), 255);
  const std::vector<std::string> names = {"ceiling", "beam", "stairs", "chair"};
  EXPECT_EQ(mapping.map_labels({0, 1, 2, 3, -1}, names),
            (std::vector<std::int32_t>{1, 255, 255, 4, 255}));

  // Ignored ground truth is skipped by the matrix, whatever was predicted.
  ConfusionMatrix matrix(mapping.evaluation_classes());
  matrix.add(mapping.map_labels({0, 1, 3}, names), {1, 20, 4});
  EXPECT_EQ(matrix.total(), 2u);
  EXPECT_EQ(matrix.skipped(), 1u);
  EXPECT_DOUBLE_EQ(*compute_metrics(matrix).miou, 1.0);
}

TEST(ClassMapping, ListsUnmappedClassesThatPointsUse) {
  const ClassMapping mapping = ClassMapping::seed_table();
  const std::vector<std::string> names = {"wall", "lamp", "stairs", "piano"};
  // piano is named but no point has it: not an error.
  EXPECT_EQ(mapping.unmapped_classes({0, 1, 2, 1}, names),
            (std::vector<std::string>{"lamp", "stairs"}));
  try {
    mapping.map_labels({0, 1, 2}, names);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lamp, stairs"), std::string::npos) << e.what();
  }
}

TEST(ClassMapping, NamesAndChecks) {
  const ClassMapping joined({{"floor", 3}, {"ceiling", 3}, {"wall", 0}}, {{0, "walls"}});
  ASSERT_EQ(joined.evaluation_classes().size(), 2u);
  EXPECT_EQ(joined.evaluation_classes()[0].name, "walls");
  EXPECT_EQ(joined.evaluation_classes()[1].name, "ceiling+floor");

  EXPECT_THROW(ClassMapping({{"wall", -2}}), std::invalid_argument);
  EXPECT_THROW(ClassMapping({{"wall", 255}}), std::invalid_argument);
  EXPECT_THROW(ClassMapping({{"", 0}}), std::invalid_argument);
  EXPECT_THROW(ClassMapping({{"wall", 0}}, {{3, "typo"}}), std::invalid_argument);
  EXPECT_THROW(ClassMapping({{"wall", 0}}, {{0, ""}}), std::invalid_argument);
  EXPECT_THROW(ClassMapping({{"wall", 0}}, {}, {"wall"}), std::invalid_argument);
  // A negative ignore id (MinkowskiEngine's -100) is fine: it is never a class.
  const ClassMapping minkowski({{"wall", 0}}, {}, {"stairs"}, -100);
  EXPECT_EQ(minkowski.find("stairs"), -100);
}

TEST(ClassMapping, Scannet20IsTheBenchmarksValidClassIds) {
  const ClassMapping mapping = ClassMapping::scannet20();
  // evaluate_semantic_label.py: VALID_CLASS_IDS and CLASS_LABELS.
  const std::vector<std::pair<std::int32_t, std::string>> expected = {
      {1, "wall"},    {2, "floor"},      {3, "cabinet"},       {4, "bed"},
      {5, "chair"},   {6, "sofa"},       {7, "table"},         {8, "door"},
      {9, "window"},  {10, "bookshelf"}, {11, "picture"},      {12, "counter"},
      {14, "desk"},   {16, "curtain"},   {24, "refrigerator"}, {28, "shower curtain"},
      {33, "toilet"}, {34, "sink"},      {36, "bathtub"},      {39, "otherfurniture"}};
  ASSERT_EQ(mapping.evaluation_classes().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(mapping.evaluation_classes()[i].id, expected[i].first);
    EXPECT_EQ(mapping.evaluation_classes()[i].name, expected[i].second);
  }
  // Ground truth named by NYU40 maps to its own id; the other NYU40 classes
  // and unannotated are skipped, as the script skips ids outside the 20.
  EXPECT_EQ(mapping.find("refridgerator"), 24);
  EXPECT_EQ(mapping.find("ceiling"), mapping.ignore_id());
  EXPECT_EQ(mapping.find("otherprop"), mapping.ignore_id());
  EXPECT_EQ(mapping.find("unannotated"), mapping.ignore_id());
  EXPECT_EQ(mapping.ignored().size(), 21u);
  EXPECT_FALSE(mapping.find("clutter").has_value());
  const std::vector<std::string> nyu40 = {"unannotated", "wall", "floor"};
  EXPECT_EQ(mapping.map_labels({2, 0, 1, -1}, nyu40),
            (std::vector<std::int32_t>{2, mapping.ignore_id(), 1, mapping.ignore_id()}));
}

TEST(ClassMapping, BuiltinsByName) {
  EXPECT_EQ(ClassMapping::builtin("table3.1")->evaluation_classes(),
            ClassMapping::seed_table().evaluation_classes());
  EXPECT_EQ(ClassMapping::builtin("scannet20")->evaluation_classes(),
            ClassMapping::scannet20().evaluation_classes());
  EXPECT_FALSE(ClassMapping::builtin("scannet200").has_value());
  EXPECT_EQ(ClassMapping::builtin_names(), (std::vector<std::string>{"table3.1", "scannet20"}));
}

}  // namespace
}  // namespace occlusion
