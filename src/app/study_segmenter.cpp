// The study's segmentation step: the built-in baseline, or the user's command.

#include <filesystem>

#include "evaluation_support.hpp"
#include "occlusion/analysis/baseline_segmenter.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/io/label_file.hpp"
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
        "the baseline segmenter predicts wall, floor, ceiling and clutter, but the "
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
  options.clutter_id = class_id(context.mapping, "clutter");
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
  if (!std::filesystem::exists(prediction_path)) {
    throw RunFailure("the segmenter wrote nothing to {output} (" + prediction_path + ")",
                     output_tail);
  }
  return load_prediction(prediction_path, request.tracing.skip_bad_lines, scanned.shift);
}

}  // namespace

std::string segmenter_name(const std::string& segmenter) {
  return is_baseline(segmenter) ? kBaselineSegmenterName : segmenter;
}

void validate_segmenter(const StudyRequest& request) {
  if (is_baseline(request.segmenter)) return;
  if (request.segmenter.find(kInput) == std::string::npos ||
      request.segmenter.find(kOutput) == std::string::npos) {
    throw KeyError("segmenter",
                   "must be 'baseline' or a command with {input} and {output} in it "
                   "(e.g. 'python infer.py {input} {output}'), got '" +
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
