#include <algorithm>
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/app/job_registry.hpp"

namespace occlusion::cli {

namespace {

std::string figure(const std::optional<double>& value) {
  return optional_figure(value, "%6.4f", "     -");
}

void print_confusion(const ConfusionMatrix& matrix) {
  std::uint64_t largest = 0;
  std::size_t name_width = 5;
  for (std::size_t r = 0; r < matrix.size(); ++r) {
    name_width = std::max(name_width, matrix.classes()[r].name.size());
    for (std::size_t c = 0; c <= matrix.size(); ++c) {
      largest = std::max(largest, matrix.count(r, c));
    }
  }
  const int width = static_cast<int>(std::max<std::size_t>(std::to_string(largest).size(), 5)) + 1;
  const int label_width = static_cast<int>(name_width) + 6;
  std::printf("  confusion (rows: ground truth, columns: predicted id)\n");
  std::printf("    %-*s", label_width, "");
  for (const auto& c : matrix.classes()) std::printf("%*d", width, c.id);
  std::printf("%*s\n", width, "other");
  for (std::size_t r = 0; r < matrix.size(); ++r) {
    const std::string label =
        matrix.classes()[r].name + " (" + std::to_string(matrix.classes()[r].id) + ")";
    std::printf("    %-*s", label_width, label.c_str());
    for (std::size_t c = 0; c <= matrix.size(); ++c) {
      std::printf("%*llu", width, static_cast<unsigned long long>(matrix.count(r, c)));
    }
    std::printf("\n");
  }
}

void print_human(const EvaluateReport& report, bool confusion) {
  const SegmentationMetrics& m = report.metrics;
  std::size_t unlabelled = 0;
  for (const auto& scene : report.scenes) unlabelled += scene.unlabelled;
  std::printf("segmentation evaluation of %zu scene(s)\n", report.scenes.size());
  std::printf("  class mapping %s (%zu evaluation classes)%s%s\n",
              report.request.mapping_path.empty() ? report.class_mapping.c_str()
                                                  : report.request.mapping_path.c_str(),
              report.confusion.size(), report.class_mapping_reason.empty() ? "" : ": ",
              report.class_mapping_reason.c_str());
  std::printf("  mIoU %s   overall accuracy %s   mean class accuracy %s\n", figure(m.miou).c_str(),
              figure(m.overall_accuracy).c_str(), figure(m.mean_class_accuracy).c_str());
  std::printf("  %llu points evaluated, %llu skipped (ground truth ignored), %zu unlabelled\n",
              static_cast<unsigned long long>(m.points), static_cast<unsigned long long>(m.skipped),
              unlabelled);
  std::printf("    %-16s %4s %10s %8s %9s %8s %8s\n", "class", "id", "support", "IoU", "precision",
              "recall", "F1");
  for (const auto& c : m.classes) {
    const bool none = c.support == 0;
    std::printf("    %-16s %4d %10llu %8s %9s %8s %8s\n", c.name.c_str(), c.id,
                static_cast<unsigned long long>(c.support),
                none ? kNoGroundTruth : figure(c.iou).c_str(), figure(c.precision).c_str(),
                figure(c.recall).c_str(), none ? kNoGroundTruth : figure(c.f1).c_str());
  }
  const std::string note = no_ground_truth_note(m);
  if (!note.empty()) std::printf("  %s\n", note.c_str());
  std::printf("  mIoU and mean class accuracy average %zu classes (mean_over %s)\n",
              m.classes_averaged, to_string(m.mean_over));
  if (report.scenes.size() > 1) {
    std::printf("  scenes:%*s points     mIoU  accuracy\n", 18, "");
    for (const auto& scene : report.scenes) {
      std::printf("    %-20s %10llu   %s    %s\n", scene.name.c_str(),
                  static_cast<unsigned long long>(scene.metrics.points),
                  figure(scene.metrics.miou).c_str(),
                  figure(scene.metrics.overall_accuracy).c_str());
    }
  }
  if (confusion) print_confusion(report.confusion);
  std::printf("  time: load %.3f s, transfer %.3f s, total %.3f s\n", report.load_seconds,
              report.transfer_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_evaluate(const JobRun& run, const FaceOptions& face) {
  print_human(run.report_as<EvaluateReport>(), face.confusion);
}

}  // namespace occlusion::cli
