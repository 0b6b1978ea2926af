// One run of the study: scan, measure, segment, score.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "evaluation_support.hpp"
#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "study_support.hpp"

namespace occlusion::job {

namespace {

std::string safe(const std::string& name) {
  std::string text;
  for (const char c : name) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.';
    text += plain ? c : '_';
  }
  return text;
}

// The viewpoints the scanned cloud's occlusion is measured from.
ViewpointChoice::Resolved measuring_viewpoints(const StudyRequest& request, const PointCloud& scene,
                                               const ViewpointChoice::Resolved& scanning) {
  if (request.occlusion_num_vp == 0) return scanning;
  // On the whole scene's box, so every configuration is measured from the same points.
  return resolve_for_cloud(ViewpointChoice::from_grid(request.occlusion_num_vp), scene,
                           request.tracing.frame, request.tracing.up);
}

// The points a scan missed, scored as -eval scores a point that received no
// label: a miss of its class (a false negative) and a false positive of none.
ConfusionMatrix missed_points_confusion(const StudyContext& context, const PointCloud& scene,
                                        const std::vector<bool>& seen, const std::string& name) {
  std::vector<bool> missed(seen.size());
  for (std::size_t i = 0; i < seen.size(); ++i) missed[i] = !seen[i];
  SceneInput hidden;
  hidden.ground_truth_name = name + " (points the scan missed)";
  hidden.ground_truth = scene.subset(missed);
  if (hidden.ground_truth.size() == 0) return ConfusionMatrix(context.mapping.evaluation_classes());
  hidden.prediction_name = "no prediction";
  hidden.prediction.labels.assign(hidden.ground_truth.size(), -1);
  return evaluate_scene(hidden, context.mapping, 0.0, 1).confusion;
}

// The analyses' own stages would flood a study's log; it reports its four
// steps (run_study_once) and forwards only the cancel flag.
Progress cancel_only(const Progress& progress) {
  Progress quiet;
  quiet.cancel = progress.cancel;
  return quiet;
}

}  // namespace

ScanRequest study_scan_request(const StudyRequest& request, const std::string& scene) {
  ScanRequest scan;
  scan.path = scene;
  scan.primitive = request.tracing.primitive;
  scan.point_radius = request.tracing.point_radius;
  scan.disc_coverage = request.tracing.disc_coverage;
  scan.normal_neighbours = request.tracing.normal_neighbours;
  scan.self_tolerance = request.self_tolerance;
  scan.octree_resolution = request.tracing.octree_resolution;
  scan.enable_acceleration = request.tracing.enable_acceleration;
  scan.format = request.format;
  scan.skip_bad_lines = request.tracing.skip_bad_lines;
  scan.threads = request.tracing.threads;
  scan.max_memory_mb = request.max_memory_mb;
  return scan;
}

std::string run_file_stem(const std::string& scene, const std::string& configuration) {
  return safe(scene) + "__" + safe(configuration);
}

StudyRow run_study_once(const StudyContext& context, const StudyRunInput& run,
                        const Progress& progress, std::vector<std::string>& warnings) {
  const StudyRequest& request = context.request;
  const PointCloud& cloud = *run.cloud;
  const Progress inner = cancel_only(progress);
  StudyRow row;
  row.run = run.index;
  row.scene = run.scene_name;
  row.configuration = run.configuration->name;
  row.points = cloud.size();
  row.segmenter = segmenter_name(request.segmenter);
  row.metrics.mean_over = request.mean_over;
  row.fingerprint = row_fingerprint(context.row_parameters, *run.configuration);
  const std::string stem = run_file_stem(run.scene_name, run.configuration->name);

  progress("scanning", 0.0);
  auto start = Clock::now();
  const ViewpointChoice::Resolved viewpoints = resolve_for_cloud(
      run.configuration->choice, cloud, request.tracing.frame, request.tracing.up);
  for (const auto& position : viewpoints.positions) {
    row.viewpoints.push_back(cloud.to_original(position));  // the table is in the file's frame
  }
  std::vector<bool> seen;
  PointCloud scanned;
  if (request.scan_model == kIdealScan) {
    const ScanReport scan =
        run_scan_on(cloud, viewpoints, study_scan_request(request, run.scene_path), inner);
    row.visible_fraction = scan.result.visible_fraction;
    seen = seen_points(scan.result);
    scanned = cloud.subset(seen);
  } else {
    SensorScan sensor = sensor_scan(request, cloud, run.scene_path, viewpoints, inner);
    seen = std::move(sensor.covered);
    scanned = std::move(sensor.scanned);
    const auto covered = static_cast<double>(std::count(seen.begin(), seen.end(), true));
    row.visible_fraction = cloud.size() == 0 ? 0.0 : covered / static_cast<double>(cloud.size());
  }
  row.scanned_points = scanned.size();
  if (scanned.size() == 0) {
    throw UsageError("configuration '" + row.configuration + "' sees no point of " + row.scene);
  }
  const std::string scanned_path = (std::filesystem::path(context.runs_dir) /
                                    (stem + ".scan." + cloud_extension(request.format)))
                                       .string();
  write_cloud(scanned_path, scanned);
  row.scan_seconds = seconds_since(start);
  progress.check_cancel();

  progress("measuring occlusion", 0.25);
  start = Clock::now();
  CloudOcclusionRequest tracing = request.tracing;
  tracing.path = run.scene_path;  // names the scene in messages
  tracing.out.clear();
  tracing.escape_directions = false;
  tracing.max_memory_mb = request.max_memory_mb;
  const CloudOcclusionReport occlusion = run_cloud_occlusion_on(
      scanned, measuring_viewpoints(request, cloud, viewpoints), context.openings, tracing, inner);
  row.occlusion_level = occlusion.result.occlusion_level;
  if (occlusion.exterior) {
    row.exterior_occlusion_level = occlusion.exterior->result.occlusion_level;
    const double ratio = occlusion.exterior->interior_exterior_ratio;
    if (std::isfinite(ratio)) row.interior_exterior_ratio = ratio;
  }
  row.occlusion_seconds = seconds_since(start);
  progress.check_cancel();

  // A segmenter that fails, or a prediction that cannot be scored, fails
  // this run alone: its row says why, and the study goes on.
  std::string output_tail;
  try {
    progress("segmenting", 0.5);
    start = Clock::now();
    SceneInput scene;
    scene.prediction = segment_scanned_cloud(context, scanned, scanned_path, stem, inner,
                                             scene.prediction_name, output_tail, warnings);
    row.segmentation_seconds = seconds_since(start);
    progress.check_cancel();

    progress("scoring", 0.75);
    start = Clock::now();
    scene.ground_truth_name = scanned_path;
    scene.ground_truth = std::move(scanned);
    // The prediction is on the scanned points (a label file, or a cloud
    // paired with them by position): nothing is transferred.
    const double no_transfer = 0.0;
    const SceneEvaluation evaluation =
        evaluate_scene(scene, context.mapping, no_transfer, request.tracing.threads, inner);
    add_scene_warnings(evaluation, no_transfer, warnings);
    ConfusionMatrix confusion = evaluation.confusion;
    if (request.scoring == "full")
      confusion += missed_points_confusion(context, cloud, seen, run.scene_path);
    row.metrics = compute_metrics(confusion, request.mean_over);
    row.evaluation_seconds = seconds_since(start);
  } catch (const RunFailure& e) {
    row.failure = e.what();
    output_tail = e.output_tail;
  } catch (const InputError& e) {
    row.failure = std::string("its prediction cannot be scored: ") + e.what();
  }
  if (!row.failure.empty()) {
    if (!output_tail.empty()) row.failure += "; segmenter output ends: " + output_tail;
    // The segmenter's output (and a prediction file quoted in a message) may
    // be any bytes; study.csv and study.md must stay text.
    row.failure = printable_text(row.failure);
    warnings.push_back(row.scene + " " + row.configuration + ": run failed: " + row.failure);
  }
  return row;
}

}  // namespace occlusion::job
