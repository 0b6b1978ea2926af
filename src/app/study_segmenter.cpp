// The study's segmentation step: the built-in baseline, the user's command
// run once per run, or the user's persistent worker (segmenter_worker.hpp).

#include <filesystem>

#include "evaluation_support.hpp"
#include "occlusion/analysis/baseline_segmenter.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/core/exact_match.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/label_file.hpp"
#include "occlusion/io/shell_quote.hpp"
#include "report_format.hpp"
#include "shell_command.hpp"
#include "study_support.hpp"

namespace occlusion::job {

namespace {

const char* const kInput = "{input}";
const char* const kOutput = "{output}";

bool is_baseline(const std::string& segmenter) {
  return segmenter == kBaselineSegmenter;
}

std::string replaced(std::string text, const std::string& placeholder, const std::string& value) {
  for (std::size_t at = text.find(placeholder); at != std::string::npos;
       at = text.find(placeholder, at + value.size())) {
    text.replace(at, placeholder.size(), value);
  }
  return text;
}

// The baseline writes the mapping's ids for these classes, so that whatever
// the mapping, -eval scores it as it stands.
std::int32_t class_id(const ClassMapping& mapping, const std::string& name) {
  const auto id = mapping.find(name);
  if (!id) {
    throw UsageError(
        "the baseline segmenter predicts wall, floor and ceiling, but the "
        "class mapping has no '" +
        name + "'");
  }
  return *id;
}

Prediction baseline(const StudyContext& context, const PointCloud& scanned, const std::string& stem,
                    const Progress& progress, std::string& prediction_path,
                    std::vector<std::string>& warnings) {
  const StudyRequest& request = context.request;
  MeshEstimate estimate;
  if (scanned.size() >= 3) {
    RegionGrowingOptions options = request.estimation;
    options.threads = request.tracing.threads;
    check_memory_budget(region_growing_memory(scanned.size(), options), request.max_memory_mb);
    try {
      estimate = estimate_mesh(scanned, options, progress);
    } catch (const NoPlaneFound& e) {
      warnings.push_back(stem + ": the baseline found no plane, so it calls every point clutter (" +
                         e.what() + ")");
    }
  }
  BaselineOptions options;
  options.snap_distance = request.estimation.ransac_distance;
  options.floor_id = class_id(context.mapping, "floor");
  options.ceiling_id = class_id(context.mapping, "ceiling");
  options.wall_id = class_id(context.mapping, "wall");
  // A mapping without clutter (scannet20: NYU40 names the objects instead)
  // leaves the baseline nothing to call the rest: it declines, and those
  // points count as misses of their classes.
  const auto clutter = context.mapping.find("clutter");
  options.clutter_id = clutter.value_or(context.mapping.ignore_id());
  if (!clutter) {
    warnings.push_back(stem +
                       ": the class mapping has no 'clutter', so the baseline leaves the points "
                       "it would call clutter unlabelled (each a miss of its class)");
  }
  Prediction prediction;
  prediction.labels = segment_baseline(scanned, estimate, options).labels;
  prediction_path =
      (std::filesystem::path(context.runs_dir) / (stem + ".baseline.labels")).string();
  write_label_file(prediction_path, prediction.labels);
  return prediction;
}

// The output's last lines on one line, for a CSV cell and a message.
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = '|';
  }
  return text;
}

std::string coordinates(const PointCloud& cloud, const Eigen::Vector3f& position) {
  const Eigen::Vector3d p = cloud.to_original(position.cast<double>());
  return "(" + format_number("%.9g", p.x()) + ", " + format_number("%.9g", p.y()) + ", " +
         format_number("%.9g", p.z()) + ")";
}

// A cloud prediction must hold the scanned cloud's points, each once, at the
// coordinates the segmenter read: then every label is paired with its point
// by position, whatever order the segmenter wrote them in. Anything else
// (points missing, added or moved) fails the run: a label paired with a point
// it was not predicted for would score as a slightly worse segmentation.
// On return the labels follow the scanned cloud's order.
void pair_with_scan(Prediction& prediction, const PointCloud& scanned,
                    const std::string& output_tail) {
  const ExactMatch match = match_exact_points(prediction.positions, scanned.positions);
  if (!match.complete()) {
    std::string reason = "its prediction holds " + std::to_string(prediction.positions.size()) +
                         " points for the " + std::to_string(scanned.size()) +
                         " points of {input}, and ";
    if (match.unmatched_targets > 0) {
      reason += std::to_string(match.unmatched_targets) +
                " points of {input} have no predicted point at their coordinates (the first: "
                "point " +
                std::to_string(match.first_unmatched_target) + " at " +
                coordinates(scanned, scanned.positions[match.first_unmatched_target]) + ")";
    }
    if (match.unmatched_sources > 0) {
      reason += std::string(match.unmatched_targets > 0 ? ", and " : "") +
                std::to_string(match.unmatched_sources) + " predicted points are none of {input}'s";
    }
    throw RunFailure(reason +
                         ". A prediction cloud is paired with {input} by position: write every "
                         "point of {input} once, with x y z as read (float32 as in the PLY, or "
                         "at least 9 significant digits in text), and its label",
                     output_tail);
  }
  std::vector<std::int32_t> labels(match.source_of.size());
  for (std::size_t i = 0; i < labels.size(); ++i) labels[i] = prediction.labels[match.source_of[i]];
  prediction.labels = std::move(labels);
  // Paired: the labels now stand for the scanned points, in their order.
  prediction.positions.clear();
}

// The prediction `prediction_path` holds, read and paired with the scan.
Prediction checked_prediction(const StudyRequest& request, const PointCloud& scanned,
                              const std::string& prediction_path, const std::string& output_tail) {
  if (!std::filesystem::exists(prediction_path)) {
    throw RunFailure("the segmenter wrote nothing to {output} (" + prediction_path + ")",
                     output_tail);
  }
  if (is_label_file(prediction_path)) {
    return load_prediction(prediction_path, request.tracing.skip_bad_lines, scanned.shift);
  }
  Prediction prediction;
  std::size_t non_finite = 0;
  try {
    prediction = load_prediction(prediction_path, request.tracing.skip_bad_lines, scanned.shift,
                                 &non_finite);
  } catch (const InputError& e) {
    // Most often a segmenter that writes bare labels where a cloud is expected.
    throw RunFailure(std::string("its prediction cannot be scored: ") + e.what() +
                         " (segmenter_output is " + request.segmenter_output +
                         ": {output} must be a cloud with x y z and a label per point; a bare "
                         "label file needs segmenter_output labels)",
                     output_tail);
  }
  // The reader drops such points, so the rest could pair completely and a
  // prediction with points {input} does not have would score ok.
  if (non_finite > 0) {
    throw RunFailure("its prediction holds " +
                         std::to_string(prediction.positions.size() + non_finite) +
                         " points for the " + std::to_string(scanned.size()) +
                         " points of {input}, " + std::to_string(non_finite) +
                         " points with a non-finite coordinate (NaN or infinity) among them, which "
                         "no point of {input} has. A prediction cloud is paired with {input} by "
                         "position: write every point of {input} once, with x y z as read, and "
                         "its label",
                     output_tail);
  }
  pair_with_scan(prediction, scanned, output_tail);
  return prediction;
}

void run_command(const StudyRequest& request, const std::string& scanned_path,
                 const std::string& prediction_path, const Progress& progress,
                 std::string& output_tail) {
  const std::string command =
      replaced(replaced(request.segmenter, kInput, shell_quote(scanned_path)), kOutput,
               shell_quote(prediction_path));
  const ShellResult result = run_shell_command(command, progress, request.segmenter_timeout);
  output_tail = one_line(result.output_tail);
  if (result.timed_out) {
    throw RunFailure("the segmenter timed out after " + std::to_string(request.segmenter_timeout) +
                         " s (segmenter_timeout) and was killed",
                     output_tail);
  }
  if (result.status != 0) {
    throw RunFailure("the segmenter failed (exit status " + std::to_string(result.status) + ")",
                     output_tail);
  }
}

void ask_worker(const StudyContext& context, const std::string& scanned_path,
                const std::string& prediction_path, const Progress& progress,
                std::string& output_tail) {
  std::string command;
  is_worker_segmenter(context.request.segmenter, &command);
  const WorkerAnswer answer = context.worker->request(command, scanned_path, prediction_path,
                                                      context.request.segmenter_timeout, progress);
  output_tail = one_line(answer.output_tail);
  if (!answer.ok) throw RunFailure(answer.failure, output_tail);
}

Prediction external(const StudyContext& context, const PointCloud& scanned,
                    const std::string& scanned_path, const std::string& stem,
                    const Progress& progress, std::string& prediction_path,
                    std::string& output_tail) {
  const StudyRequest& request = context.request;
  prediction_path =
      (std::filesystem::path(context.runs_dir) / (stem + ".prediction." + request.segmenter_output))
          .string();
  // A stale prediction of an earlier attempt must not pass for this one's.
  std::filesystem::remove(prediction_path);
  if (is_worker_segmenter(request.segmenter)) {
    ask_worker(context, scanned_path, prediction_path, progress, output_tail);
  } else {
    run_command(request, scanned_path, prediction_path, progress, output_tail);
  }
  return checked_prediction(request, scanned, prediction_path, output_tail);
}

}  // namespace

std::string segmenter_name(const std::string& segmenter) {
  return is_baseline(segmenter) ? kBaselineSegmenterName : segmenter;
}

void validate_segmenter(const StudyRequest& request) {
  if (is_baseline(request.segmenter)) return;
  std::string worker;
  if (is_worker_segmenter(request.segmenter, &worker)) {
    if (worker.empty() || worker.find(kInput) != std::string::npos ||
        worker.find(kOutput) != std::string::npos) {
      throw KeyError("segmenter",
                     "a worker is 'worker: COMMAND', a command that reads one 'INPUT<TAB>OUTPUT' "
                     "line per run on stdin and answers 'ok' (no {input} or {output} in it: "
                     "each run's paths come on its stdin), got '" +
                         request.segmenter + "'");
    }
    return;
  }
  if (request.segmenter.find(kInput) == std::string::npos ||
      request.segmenter.find(kOutput) == std::string::npos) {
    throw KeyError("segmenter",
                   "must be 'baseline', a command with {input} and {output} in it "
                   "(e.g. 'python infer.py {input} {output}') or 'worker: COMMAND', got '" +
                       request.segmenter + "'");
  }
}

Prediction segment_scanned_cloud(const StudyContext& context, const PointCloud& scanned,
                                 const std::string& scanned_path, const std::string& stem,
                                 const Progress& progress, std::string& prediction_path,
                                 std::string& output_tail, std::vector<std::string>& warnings) {
  if (is_baseline(context.request.segmenter)) {
    return baseline(context, scanned, stem, progress, prediction_path, warnings);
  }
  return external(context, scanned, scanned_path, stem, progress, prediction_path, output_tail);
}

}  // namespace occlusion::job
