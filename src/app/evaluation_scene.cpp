// evaluate_scene and load_scene: from a ground truth and a prediction to one
// scene's confusion matrix.

#include <algorithm>
#include <filesystem>
#include <set>

#include "evaluation_support.hpp"
#include "job_support.hpp"
#include "occlusion/analysis/label_transfer.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/core/exact_match.hpp"
#include "occlusion/core/nyu40_classes.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/label_file.hpp"
#include "report_format.hpp"

namespace occlusion {

namespace {

std::string scene_name(const std::string& path) {
  std::filesystem::path p(path);
  if (p.filename().empty()) p = p.parent_path();
  return p.stem().string();
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// The ground truth's labels as evaluation ids.
std::vector<std::int32_t> ground_truth_ids(const SceneInput& scene, const ClassMapping& mapping) {
  job::check_ground_truth(scene.ground_truth_name, scene.ground_truth, mapping);
  return mapping.map_labels(scene.ground_truth.labels, scene.ground_truth.class_names);
}

// The prediction's labels as evaluation ids, still on its own points.
std::vector<std::int32_t> prediction_ids(const SceneInput& scene, const ClassMapping& mapping) {
  const Prediction& prediction = scene.prediction;
  if (prediction.class_names.empty()) return prediction.labels;
  const auto unmapped = mapping.unmapped_classes(prediction.labels, prediction.class_names);
  if (!unmapped.empty()) {
    throw UsageError(scene.prediction_name + ": classes not in the class mapping: " +
                     joined(unmapped) + " (a prediction that names its classes is mapped by name)");
  }
  std::vector<std::int32_t> ids = mapping.map_labels(prediction.labels, prediction.class_names);
  // map_labels turns "no label" into the ignore id; keep -1 so it counts as unlabelled.
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (prediction.labels[i] < 0) ids[i] = -1;
  }
  return ids;
}

// The fraction of scored ground-truth points (labelled, not ignored) that
// predicted[at(i)] gets right, point i taking the label at(i).
template <typename At>
double agreement(const std::vector<std::int32_t>& truth, const std::vector<std::int32_t>& predicted,
                 std::int32_t ignore_id, At at) {
  std::size_t scored = 0;
  std::size_t right = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i] < 0 || truth[i] == ignore_id) continue;
    ++scored;
    right += predicted[at(i)] == truth[i] ? 1 : 0;
  }
  return scored == 0 ? 0.0 : static_cast<double>(right) / static_cast<double>(scored);
}

// A label file written in Annotations order for an S3DIS room, whose points
// follow <room>.txt, scores like noise while being right: the misalignment of
// issue 12. Where both orders exist, a file that agrees with the ground truth
// far better in Annotations order (over half the points, and 25 points more in
// a hundred) is refused; a real prediction in the right order cannot do that,
// since its labels would then have to match two unrelated pairings at once.
void refuse_annotation_order(const SceneInput& scene, const std::vector<std::int32_t>& truth,
                             const std::vector<std::int32_t>& predicted, std::int32_t ignore_id) {
  const std::vector<std::size_t>& order = scene.annotation_order;
  if (order.size() != truth.size()) return;
  bool differs = false;
  for (std::size_t i = 0; i < order.size() && !differs; ++i) differs = order[i] != i;
  if (!differs) return;
  const double as_given = agreement(truth, predicted, ignore_id, [](std::size_t i) { return i; });
  const double as_annotations =
      agreement(truth, predicted, ignore_id, [&](std::size_t i) { return order[i]; });
  if (as_annotations >= 0.5 && as_annotations >= as_given + 0.25) {
    throw UsageError(
        scene.prediction_name + ": its labels match " + scene.ground_truth_name + " on " +
        job::format_number("%.1f%%", 100.0 * as_given) + " of the points in the order labels " +
        "follow (<room>.txt's, docs/formats.md) but on " +
        job::format_number("%.1f%%", 100.0 * as_annotations) +
        " if read in Annotations order: they were written in the annotation files' order. "
        "Write them in the order of <room>.txt, or give the prediction as a cloud with "
        "coordinates (x y z label)");
  }
}

bool same_points(const PointCloud& ground_truth, const Prediction& prediction) {
  return prediction.positions.size() == ground_truth.size() &&
         std::equal(prediction.positions.begin(), prediction.positions.end(),
                    ground_truth.positions.begin());
}

}  // namespace

SceneEvaluation evaluate_scene(const SceneInput& scene, const ClassMapping& mapping,
                               double max_distance, unsigned threads, const Progress& progress) {
  SceneEvaluation result;
  result.name = scene_name(scene.ground_truth_name);
  result.ground_truth = scene.ground_truth_name;
  result.prediction = scene.prediction_name;
  result.points = scene.ground_truth.size();
  result.prediction_points = scene.prediction.labels.size();
  const std::vector<std::int32_t> truth = ground_truth_ids(scene, mapping);
  std::vector<std::int32_t> predicted = prediction_ids(scene, mapping);

  const Prediction& prediction = scene.prediction;
  if (prediction.positions.empty()) {
    if (prediction.labels.size() != truth.size()) {
      throw InputError(scene.prediction_name, 0,
                       "holds " + std::to_string(prediction.labels.size()) + " labels for the " +
                           std::to_string(truth.size()) + " points of " + scene.ground_truth_name +
                           " (a label file has one label per ground-truth point, in order)");
    }
    refuse_annotation_order(scene, truth, predicted, mapping.ignore_id());
    result.transfer = "direct";
  } else if (same_points(scene.ground_truth, prediction)) {
    result.transfer = "direct";
  } else if (max_distance <= 0.0) {
    // The same points in another order are paired by their coordinates.
    const ExactMatch match = match_exact_points(prediction.positions, scene.ground_truth.positions);
    if (!match.complete()) {
      throw UsageError(scene.prediction_name + ": its points are not those of " +
                       scene.ground_truth_name + " (" + std::to_string(match.unmatched_targets) +
                       " ground-truth points have no prediction point at the same coordinates); "
                       "--max-distance 0 needs the same points (give a distance > 0 to transfer "
                       "labels by nearest neighbour)");
    }
    std::vector<std::int32_t> paired(match.source_of.size());
    for (std::size_t i = 0; i < paired.size(); ++i) paired[i] = predicted[match.source_of[i]];
    predicted = std::move(paired);
    result.transfer = "matched_by_position";
  } else {
    LabelTransferOptions options;
    options.max_distance = max_distance;
    options.threads = threads;
    const LabelTransfer transfer = transfer_labels(prediction.positions, predicted,
                                                   scene.ground_truth.positions, options, progress);
    predicted = transfer.labels;
    result.transfer = "nearest_neighbour";
    result.beyond_distance = transfer.beyond_distance;
    result.max_matched_distance = transfer.max_matched_distance;
    result.transfer_seconds = transfer.seconds;
  }

  result.confusion = ConfusionMatrix(mapping.evaluation_classes());
  result.confusion.add(truth, predicted);
  result.metrics = compute_metrics(result.confusion);
  std::set<std::int32_t> foreign;
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    const std::int32_t id = predicted[i];
    if (id < 0) {
      ++result.unlabelled;
    } else if (id != mapping.ignore_id() && !result.confusion.index_of(id) &&
               result.confusion.index_of(truth[i])) {
      // Only where it counted: on a skipped ground-truth point (unannotated,
      // an ignored class) a foreign id is no miss, and warning of one would
      // not be true.
      foreign.insert(id);
    }
  }
  result.foreign_predictions.assign(foreign.begin(), foreign.end());
  return result;
}

namespace job {

BuiltinMappingChoice choose_builtin_mapping(const std::string& name, const PointCloud& cloud) {
  if (cloud.class_names != nyu40_class_names()) return {ClassMapping::kDefaultBuiltin, ""};
  return {"scannet20", name +
                           " is labelled with NYU40 classes (a ScanNet scene): scored over the "
                           "ScanNet v2 benchmark's 20 classes, as ScanNet's "
                           "evaluate_semantic_label.py scores it"};
}

void check_ground_truth(const std::string& name, const PointCloud& cloud,
                        const ClassMapping& mapping) {
  if (!cloud.has_labels()) {
    throw InputError(name, 0,
                     "has no labels; the ground truth must be a labelled cloud (PLY or PCD with "
                     "a label field, an S3DIS room or Area)");
  }
  if (cloud.class_names.empty()) {
    throw InputError(name, 0,
                     "its labels have no class names, so the class mapping cannot apply: give "
                     "a class_names file (one name per line, line k naming label k), or a cloud "
                     "that names them (PLY and PCD files written by occlusion keep them as header "
                     "comments; ScanNet scenes get the NYU40 names)");
  }
  const bool nyu40 = cloud.class_names == nyu40_class_names();
  // Table 3.1 knows wall, floor, chair, ... by the same names, so a ScanNet
  // scene holding only those would be scored in table 3.1's ids, not the
  // NYU40 ids its predictions use: a wrong mIoU with no error.
  if (nyu40 && mapping.ids() == ClassMapping::seed_table().ids()) {
    throw UsageError(name +
                     ": its labels are NYU40 classes (a ScanNet scene), which the seed's table "
                     "3.1 does not score: use class_mapping scannet20 (auto, the default, "
                     "chooses it), or a mapping file with its own classes");
  }
  const auto unmapped = mapping.unmapped_classes(cloud.labels, cloud.class_names);
  if (!unmapped.empty()) {
    throw UsageError(name + ": classes not in the class mapping: " + joined(unmapped) +
                     (nyu40 ? " (its labels are NYU40 classes, as ScanNet's: score them with "
                              "class_mapping scannet20, or map them in a mapping file)"
                            : " (map them, or list them in ignored_classes)"));
  }
}

namespace {

std::string percent(std::size_t part, std::size_t whole) {
  return job::format_number("%.1f%%", 100.0 * static_cast<double>(part) /
                                          static_cast<double>(std::max<std::size_t>(whole, 1)));
}

}  // namespace

void add_scene_warnings(const SceneEvaluation& scene, double max_distance,
                        std::vector<std::string>& warnings) {
  if (scene.beyond_distance > 0) {
    warnings.push_back(scene.name + ": " + std::to_string(scene.beyond_distance) + " of " +
                       std::to_string(scene.points) + " ground-truth points (" +
                       percent(scene.beyond_distance, scene.points) +
                       ") have no predicted point within " +
                       job::format_number("%g", max_distance) + "; they count as misses");
  }
  if (!scene.foreign_predictions.empty()) {
    std::string ids;
    for (std::size_t i = 0; i < scene.foreign_predictions.size() && i < 10; ++i) {
      ids += (ids.empty() ? "" : ", ") + std::to_string(scene.foreign_predictions[i]);
    }
    if (scene.foreign_predictions.size() > 10) ids += ", ...";
    warnings.push_back(scene.name + ": predicted ids " + ids +
                       " are no evaluation class and count as misses (are the predictions in "
                       "the mapping's evaluation ids?)");
  }
  if (scene.metrics.points == 0) {
    warnings.push_back(scene.name + ": no ground-truth point is in an evaluation class");
  }
}

Prediction load_prediction(const std::string& path, bool skip_bad_lines,
                           const Eigen::Vector3d& shift, std::size_t* non_finite) {
  Prediction prediction;
  if (non_finite != nullptr) *non_finite = 0;
  if (is_label_file(path)) {
    prediction.labels = read_label_file(path);
    return prediction;
  }
  LoadedCloud predicted = load_cloud(path, skip_bad_lines, shift);
  if (non_finite != nullptr) *non_finite = predicted.dropped_nan;
  if (!predicted.cloud.has_labels()) {
    throw InputError(path, 0, "has no labels; a prediction is a labelled cloud or a label file");
  }
  prediction.labels = std::move(predicted.cloud.labels);
  prediction.positions = std::move(predicted.cloud.positions);
  prediction.class_names = std::move(predicted.cloud.class_names);
  return prediction;
}

namespace {

// A label file is paired with the ground truth by point order alone, so the
// order must be one the user can know: refused when reading dropped points
// (the lines no longer line up) or when an S3DIS room's order could not be
// checked against its <room>.txt (the labels may follow that file or the
// Annotations, and nothing tells which).
void check_label_order(const std::string& prediction, const std::string& ground_truth,
                       const LoadedCloud& truth) {
  if (truth.dropped_nan + truth.skipped_lines > 0) {
    throw InputError(prediction, 0,
                     "labels are given by point order, but reading " + ground_truth + " dropped " +
                         std::to_string(truth.dropped_nan + truth.skipped_lines) +
                         " points (NaN or skipped lines), so they no longer line up");
  }
  if (!truth.unverified_order.empty()) {
    throw UsageError(
        prediction + ": a label file is paired with " + ground_truth +
        " by point order, and that order cannot be verified (" + joined(truth.unverified_order) +
        "). Give each room a <room>.txt holding exactly its annotated points in the order of "
        "your labels, or give the prediction as a cloud with coordinates (x y z label) so "
        "points are paired by position");
  }
}

}  // namespace

LoadedScene load_scene(const std::string& ground_truth, const std::string& prediction,
                       bool skip_bad_lines, const std::string& class_names_path) {
  LoadedScene scene;
  LoadedCloud truth = load_cloud(ground_truth, skip_bad_lines);
  name_classes(truth.cloud, ground_truth, class_names_path);
  scene.input.ground_truth_name = ground_truth;
  scene.input.ground_truth = std::move(truth.cloud);
  scene.input.prediction_name = prediction;
  scene.dropped_nan = truth.dropped_nan;
  scene.skipped_lines = truth.skipped_lines;
  if (is_label_file(prediction)) {
    check_label_order(prediction, ground_truth, truth);
    scene.input.annotation_order = std::move(truth.annotation_order);
  }
  scene.input.prediction = load_prediction(
      prediction, skip_bad_lines, scene.input.ground_truth.shift, &scene.prediction_non_finite);
  return scene;
}

}  // namespace job

}  // namespace occlusion
