#pragma once
// The `evaluate` job (-eval): how good is a semantic segmentation, scene by
// scene and over all scenes, against labelled ground truth. Ground-truth
// classes are mapped by name to evaluation ids (class_mapping_file.hpp);
// predictions are evaluation ids, given per ground-truth point (a label file,
// or a cloud with the same points) or on other points (a voxelised network
// output), whose labels are then carried over by nearest neighbour within
// max_distance. The scenes' confusion matrices are summed. docs/metrics.md
// has every convention and formula.

#include <json/value.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/analysis/class_mapping.hpp"
#include "occlusion/analysis/confusion_matrix.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct EvaluateRequest {
  std::vector<std::string> ground_truth;  // labelled clouds with class names, one per scene
  std::vector<std::string> predictions;   // same count and order: clouds or label files
  // A built-in (table3.1 or scannet20), or ClassMapping::kByGroundTruth:
  // chosen by the first ground truth's class names (choose_builtin_mapping).
  std::string class_mapping = ClassMapping::kByGroundTruth;
  std::string mapping_path;                  // empty: class_mapping as it is
  std::vector<std::string> ignored_classes;  // skipped on top of the mapping's
  double max_distance = 0.05;  // for label transfer; 0: points must be the ground truth's
  // Which classes mIoU and mean class accuracy average over (confusion_matrix.hpp).
  MeanOver mean_over = MeanOver::support;
  bool skip_bad_lines = false;
  std::string class_names_path;  // names the ground truths' labels; "" = none
  unsigned threads = 0;
  std::string out;
};

// A scene's predictions, in evaluation ids (-1: no label).
struct Prediction {
  std::vector<std::int32_t> labels;
  // The points the labels belong to; empty when labels[i] is ground-truth
  // point i's (a label file).
  std::vector<Eigen::Vector3f> positions;
  // Class names of a prediction cloud that has them: its labels index these,
  // and are mapped by name like the ground truth's.
  std::vector<std::string> class_names;
};

// One scene, in memory: what the job loads from files, or what another job
// (the occlusion study) already holds. The names label messages and reports.
struct SceneInput {
  std::string ground_truth_name;
  PointCloud ground_truth;
  // For an S3DIS ground truth, each point's place in Annotations order
  // (CloudReadReport::annotation_order): a label file that agrees with the
  // ground truth far better in that order than in the points' own is refused
  // as misaligned. Empty: no other order to suspect.
  std::vector<std::size_t> annotation_order;
  std::string prediction_name;
  Prediction prediction;
};

struct SceneEvaluation {
  std::string name;  // the ground truth's file stem
  std::string ground_truth;
  std::string prediction;
  // "direct" (same order), "matched_by_position" (the same points in another
  // order, max_distance 0) or "nearest_neighbour"
  std::string transfer;
  std::size_t points = 0;             // ground-truth points
  std::size_t prediction_points = 0;  // predicted labels given
  std::size_t unlabelled = 0;         // ground-truth points left without a prediction
  std::size_t beyond_distance = 0;    // of those, for want of a point within max_distance
  double max_matched_distance = 0.0;
  double transfer_seconds = 0.0;
  // Predicted ids that are no evaluation class, on points that count (ground
  // truth in an evaluation class): each such prediction is a miss.
  std::vector<std::int32_t> foreign_predictions;
  ConfusionMatrix confusion;
  SegmentationMetrics metrics;
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
};

struct EvaluateReport {
  EvaluateRequest request;
  // The built-in mapping used (the request's, or the one chosen for its
  // ground truth) and, when chosen, why: the report says so.
  std::string class_mapping;
  std::string class_mapping_reason;
  ClassMapping mapping = ClassMapping::seed_table();
  std::vector<SceneEvaluation> scenes;
  ConfusionMatrix confusion;  // the scenes' matrices summed
  SegmentationMetrics metrics;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0;
  double transfer_seconds = 0.0;
  double total_seconds = 0.0;
};

void validate(const EvaluateRequest& request);
// Every key of the job (config section occlusion.evaluate), declared once.
const Keys<EvaluateRequest>& evaluate_keys();
// The built-in mapping `class_mapping` names (ClassMapping::builtin), narrowed
// by a mapping file (or replaced by one that gives its own classes), with
// `ignored_classes` added. UsageError for a bad file, and for a file with its
// own classes beside a built-in other than the default (one would be ignored).
ClassMapping resolve_mapping(const std::string& class_mapping, const std::string& mapping_path,
                             const std::vector<std::string>& ignored_classes);

// Evaluates one scene. Predictions on the ground truth's own points (same
// count and positions, or a label file) are compared directly; with
// max_distance 0, the same points in another order are paired by identical
// coordinates; others are transferred by nearest neighbour within max_distance. InputError naming
// the file for a ground truth without labels or class names and for a label
// count that differs from the point count; UsageError for classes the
// mapping does not know, or other points with max_distance 0.
// load_scene (evaluation_support.hpp) refuses, before this, a label file whose
// pairing by order cannot be verified.
SceneEvaluation evaluate_scene(const SceneInput& scene, const ClassMapping& mapping,
                               double max_distance, unsigned threads,
                               const Progress& progress = {});

EvaluateReport run_evaluate(const EvaluateRequest& request, const Progress& progress = {});

// The tables (text, Markdown) show a class without ground-truth points as
// having none (kNoGroundTruth in its IoU and F1 cells) rather than a 0 that
// reads as a score; this note, empty when every class has some, counts them
// and says whether the means take them in (the rule of `metrics`).
inline constexpr const char* kNoGroundTruth = "no gt";
std::string no_ground_truth_note(const SegmentationMetrics& metrics);

// Headline: miou (null when no class has ground truth).
Json::Value to_json(const EvaluateReport& report);
// Pieces of the report, for other jobs that evaluate.
Json::Value to_json(const SegmentationMetrics& metrics);
Json::Value to_json(const ConfusionMatrix& matrix);

}  // namespace occlusion
