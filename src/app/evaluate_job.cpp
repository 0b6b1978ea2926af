#include "occlusion/app/evaluate_job.hpp"

#include <algorithm>
#include <optional>

#include "evaluation_support.hpp"
#include "job_support.hpp"
#include "occlusion/app/class_mapping_file.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {

namespace {

Json::Value mapping_json(const EvaluateReport& report) {
  const ClassMapping& mapping = report.mapping;
  const EvaluateRequest& q = report.request;
  Json::Value json(Json::objectValue);
  json["builtin"] = report.class_mapping;
  json["requested"] = q.class_mapping;
  json["chosen_because"] = report.class_mapping_reason.empty()
                               ? Json::Value()
                               : Json::Value(report.class_mapping_reason);
  json["source"] = q.mapping_path.empty() ? "built-in " + report.class_mapping : q.mapping_path;
  json["ignore"] = mapping.ignore_id();
  json["ignored_classes"] =
      to_json(std::vector<std::string>(mapping.ignored().begin(), mapping.ignored().end()));
  Json::Value classes(Json::arrayValue);
  for (const auto& c : mapping.evaluation_classes()) {
    Json::Value entry(Json::objectValue);
    entry["id"] = c.id;
    entry["name"] = c.name;
    std::vector<std::string> members;
    for (const auto& [name, id] : mapping.ids()) {
      if (id == c.id && mapping.ignored().count(name) == 0) members.push_back(name);
    }
    entry["ground_truth_classes"] = to_json(members);
    classes.append(entry);
  }
  json["evaluation_classes"] = classes;
  return json;
}

Json::Value scene_json(const SceneEvaluation& scene) {
  Json::Value json = to_json(scene.metrics);
  json["name"] = scene.name;
  json["ground_truth"] = scene.ground_truth;
  json["prediction"] = scene.prediction;
  json["transfer"] = scene.transfer;
  json["ground_truth_points"] = Json::UInt64(scene.points);
  json["prediction_points"] = Json::UInt64(scene.prediction_points);
  json["unlabelled_points"] = Json::UInt64(scene.unlabelled);
  json["beyond_distance_points"] = Json::UInt64(scene.beyond_distance);
  json["max_matched_distance"] = scene.max_matched_distance;
  Json::Value foreign(Json::arrayValue);
  for (const auto id : scene.foreign_predictions) foreign.append(id);
  json["foreign_prediction_ids"] = foreign;
  json["dropped_nan_points"] = Json::UInt64(scene.dropped_nan);
  json["skipped_lines"] = Json::UInt64(scene.skipped_lines);
  json["confusion"] = to_json(scene.confusion);
  return json;
}

// The reader drops prediction points with a non-finite coordinate. Paired
// by position (max_distance 0), the rest could then pair completely with the
// ground truth and a prediction holding points it does not have would score
// as if it were right; a transfer by nearest neighbour has no use for them.
void check_non_finite_predictions(const job::LoadedScene& loaded, double max_distance,
                                  std::vector<std::string>& warnings) {
  const std::size_t count = loaded.prediction_non_finite;
  if (count == 0) return;
  const std::string what = std::to_string(count) +
                           " points with a non-finite coordinate (NaN or infinity), which no "
                           "point of " +
                           loaded.input.ground_truth_name + " has";
  if (max_distance <= 0.0) {
    throw InputError(loaded.input.prediction_name, 0,
                     "holds " + what +
                         ": with --max-distance 0 a prediction cloud is paired with the ground "
                         "truth by position, so write every ground-truth point once, with x y z "
                         "as read, and its label (or give a distance > 0 to transfer labels by "
                         "nearest neighbour, which leaves such points out)");
  }
  warnings.push_back(loaded.input.prediction_name + ": " + what +
                     "; the transfer by nearest neighbour leaves them out");
}

}  // namespace

void validate(const EvaluateRequest& request) {
  if (request.ground_truth.empty()) {
    throw UsageError(
        "no ground truth given (-eval GT --prediction PRED, or occlusion.evaluate.ground_truth)");
  }
  if (request.predictions.size() != request.ground_truth.size()) {
    throw UsageError(std::to_string(request.ground_truth.size()) + " ground truth(s) but " +
                     std::to_string(request.predictions.size()) +
                     " prediction(s): give --prediction once per ground truth, in the same order");
  }
  check_keys(evaluate_keys(), request);
}

ClassMapping resolve_mapping(const std::string& class_mapping, const std::string& mapping_path,
                             const std::vector<std::string>& ignored_classes) {
  const std::optional<ClassMapping> base = ClassMapping::builtin(class_mapping);
  if (!base) throw KeyError("class_mapping", "has no built-in mapping '" + class_mapping + "'");
  if (!mapping_path.empty() && class_mapping != ClassMapping::kDefaultBuiltin &&
      mapping_file_has_classes(mapping_path)) {
    throw KeyError("class_mapping",
                   "names the built-in mapping '" + class_mapping + "', but the mapping file " +
                       mapping_path +
                       " gives its own 'classes', which replace it: give one or the other (a "
                       "file without 'classes' narrows the built-in mapping)");
  }
  const ClassMapping mapping =
      mapping_path.empty() ? *base : load_class_mapping(mapping_path, *base);
  if (ignored_classes.empty()) return mapping;
  try {
    return mapping.with_ignored(ignored_classes);
  } catch (const std::invalid_argument& e) {
    throw KeyError("ignored_classes", std::string("is wrong: ") + e.what());
  }
}

EvaluateReport run_evaluate(const EvaluateRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  EvaluateReport report;
  report.request = request;
  report.class_mapping = request.class_mapping;
  // A mapping the request names is checked before any scene is read; one
  // chosen by the ground truth once the first is.
  const bool by_ground_truth = request.class_mapping == ClassMapping::kByGroundTruth;
  const auto use_mapping = [&](const std::string& builtin) {
    report.class_mapping = builtin;
    report.mapping = resolve_mapping(builtin, request.mapping_path, request.ignored_classes);
    report.confusion = ConfusionMatrix(report.mapping.evaluation_classes());
  };
  if (!by_ground_truth) use_mapping(request.class_mapping);

  const std::size_t count = request.ground_truth.size();
  for (std::size_t k = 0; k < count; ++k) {
    progress("loading", static_cast<double>(k) / static_cast<double>(count));
    const auto load_start = job::Clock::now();
    const job::LoadedScene loaded =
        job::load_scene(request.ground_truth[k], request.predictions[k], request.skip_bad_lines,
                        request.class_names_path);
    report.load_seconds += job::seconds_since(load_start);
    progress.check_cancel();
    if (k == 0 && by_ground_truth) {
      // A mapping file with its own classes replaces any built-in.
      const bool own_classes =
          !request.mapping_path.empty() && mapping_file_has_classes(request.mapping_path);
      const job::BuiltinMappingChoice choice =
          own_classes ? job::BuiltinMappingChoice{ClassMapping::kDefaultBuiltin, ""}
                      : job::choose_builtin_mapping(loaded.input.ground_truth_name,
                                                    loaded.input.ground_truth);
      use_mapping(choice.name);
      report.class_mapping_reason = choice.reason;
    }
    check_non_finite_predictions(loaded, request.max_distance, report.warnings);

    SceneEvaluation scene = evaluate_scene(loaded.input, report.mapping, request.max_distance,
                                           request.threads, progress);
    scene.metrics = compute_metrics(scene.confusion, request.mean_over);
    scene.dropped_nan = loaded.dropped_nan;
    scene.skipped_lines = loaded.skipped_lines;
    report.transfer_seconds += scene.transfer_seconds;
    job::add_scene_warnings(scene, request.max_distance, report.warnings);
    report.confusion += scene.confusion;
    report.scenes.push_back(std::move(scene));
  }
  report.metrics = compute_metrics(report.confusion, request.mean_over);
  progress("done", 1.0);

  if (!request.out.empty()) {
    ensure_directory(request.out);
    // One scene: named after it, like the other jobs' outputs; several: one summary.
    const auto path = [&](const std::string& extension) {
      return count == 1
                 ? job::output_path(request.out, request.ground_truth[0], ".eval" + extension)
                 : job::output_path(request.out, "eval", extension);
    };
    const std::string json_path = path(".json");
    const std::string csv_path = path(".csv");
    const std::string markdown_path = path(".md");
    OutputSet outputs;
    job::write_evaluation_csv(outputs.add(csv_path), report);
    job::write_evaluation_markdown(outputs.add(markdown_path), report);
    job::commit_outputs(outputs, report, json_path, {json_path, csv_path, markdown_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

Json::Value to_json(const SegmentationMetrics& metrics) {
  Json::Value json(Json::objectValue);
  json["miou"] = to_json(metrics.miou);
  json["overall_accuracy"] = to_json(metrics.overall_accuracy);
  json["mean_class_accuracy"] = to_json(metrics.mean_class_accuracy);
  json["mean_over"] = to_string(metrics.mean_over);
  json["classes_averaged"] = Json::UInt64(metrics.classes_averaged);
  json["classes_with_support"] = Json::UInt64(metrics.classes_with_support);
  json["points"] = Json::UInt64(metrics.points);
  json["correct_points"] = Json::UInt64(metrics.correct);
  json["other_predictions"] = Json::UInt64(metrics.other);
  json["skipped_points"] = Json::UInt64(metrics.skipped);
  Json::Value classes(Json::arrayValue);
  for (const auto& c : metrics.classes) {
    Json::Value entry(Json::objectValue);
    entry["id"] = c.id;
    entry["name"] = c.name;
    entry["support"] = Json::UInt64(c.support);
    entry["tp"] = Json::UInt64(c.tp);
    entry["fp"] = Json::UInt64(c.fp);
    entry["fn"] = Json::UInt64(c.fn);
    entry["iou"] = to_json(c.iou);
    entry["precision"] = to_json(c.precision);
    entry["recall"] = to_json(c.recall);
    entry["f1"] = to_json(c.f1);
    entry["averaged"] = c.averaged;
    classes.append(entry);
  }
  json["classes"] = classes;
  return json;
}

Json::Value to_json(const ConfusionMatrix& matrix) {
  Json::Value json(Json::objectValue);
  Json::Value ids(Json::arrayValue);
  Json::Value names(Json::arrayValue);
  for (const auto& c : matrix.classes()) {
    ids.append(c.id);
    names.append(c.name);
  }
  json["ids"] = ids;
  json["names"] = names;
  Json::Value rows(Json::arrayValue);
  for (std::size_t r = 0; r < matrix.size(); ++r) {
    Json::Value row(Json::arrayValue);
    for (std::size_t c = 0; c <= matrix.size(); ++c) row.append(Json::UInt64(matrix.count(r, c)));
    rows.append(row);
  }
  json["rows"] = rows;
  json["skipped"] = Json::UInt64(matrix.skipped());
  return json;
}

Json::Value to_json(const EvaluateReport& report) {
  const EvaluateRequest& q = report.request;
  Json::Value json = to_json(report.metrics);
  json["job"] = "evaluate";
  std::size_t unlabelled = 0;
  std::size_t beyond = 0;
  Json::Value scenes(Json::arrayValue);
  for (const auto& scene : report.scenes) {
    unlabelled += scene.unlabelled;
    beyond += scene.beyond_distance;
    scenes.append(scene_json(scene));
  }
  json["unlabelled_points"] = Json::UInt64(unlabelled);
  json["beyond_distance_points"] = Json::UInt64(beyond);
  json["confusion"] = to_json(report.confusion);
  json["scenes"] = scenes;
  json["mapping"] = mapping_json(report);

  json["parameters"] = parameters_json(evaluate_keys(), q);

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  timings["transfer_seconds"] = report.transfer_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
