// The study's segmentation step: the built-in baseline, or the user's command.

#include <filesystem>
#include <stdexcept>

#include "evaluation_support.hpp"
#include "occlusion/analysis/baseline_segmenter.hpp"
#include "occlusion/app/errors.hpp"
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

Prediction external(const StudyContext& context, const std::string& scanned_path,
                    const std::string& stem, const Progress& progress,
                    std::string& prediction_path) {
  const StudyRequest& request = context.request;
  prediction_path =
      (std::filesystem::path(context.runs_dir) / (stem + ".prediction." + request.segmenter_output))
          .string();
  // A stale prediction of an earlier attempt must not pass for this one's.
  std::filesystem::remove(prediction_path);
  const std::string command =
      replaced(replaced(request.segmenter, kInput, shell_quote(scanned_path)), kOutput,
               shell_quote(prediction_path));
  const int status = run_shell_command(command, progress);
  if (status != 0) {
    throw std::runtime_error("the segmenter failed (exit status " + std::to_string(status) +
                             ") on " + scanned_path + ": " + command);
  }
  if (!std::filesystem::exists(prediction_path)) {
    throw std::runtime_error("the segmenter wrote nothing to {output} (" + prediction_path +
                             "): " + command);
  }
  return load_prediction(prediction_path, request.tracing.skip_bad_lines);
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
                                 std::vector<std::string>& warnings) {
  if (is_baseline(context.request.segmenter)) {
    return baseline(context, scanned, stem, progress, prediction_path, warnings);
  }
  return external(context, scanned_path, stem, progress, prediction_path);
}

}  // namespace occlusion::job
