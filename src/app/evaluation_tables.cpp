// The evaluate job's CSV and Markdown reports.

#include <ostream>

#include "evaluation_support.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/csv_file.hpp"
#include "report_format.hpp"

namespace occlusion::job {

namespace {

std::string figure(const std::optional<double>& value, const char* missing) {
  return format_number("%.6g", value, missing);
}

std::string fixed(const std::optional<double>& value) {
  return format_number("%.4f", value, "–");
}

void csv_rows(std::ostream& out, const std::string& scene, const SegmentationMetrics& metrics) {
  for (const auto& c : metrics.classes) {
    out << csv_field(scene) << ',' << c.id << ',' << csv_field(c.name) << ',' << c.support << ','
        << c.tp << ',' << c.fp << ',' << c.fn << ',' << figure(c.iou, "") << ','
        << figure(c.precision, "") << ',' << figure(c.recall, "") << ',' << figure(c.f1, "")
        << '\n';
  }
}

}  // namespace

void write_evaluation_csv(const std::string& path, const EvaluateReport& report) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "scene,id,class,support,tp,fp,fn,iou,precision,recall,f1\n";
    csv_rows(out, "total", report.metrics);
    if (report.scenes.size() > 1) {
      for (const auto& scene : report.scenes) csv_rows(out, scene.name, scene.metrics);
    }
  });
}

void write_evaluation_markdown(const std::string& path, const EvaluateReport& report) {
  const SegmentationMetrics& m = report.metrics;
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# Segmentation evaluation\n\n"
        << "| mIoU | overall accuracy | mean class accuracy | points | scenes |\n"
        << "|---:|---:|---:|---:|---:|\n"
        << "| " << fixed(m.miou) << " | " << fixed(m.overall_accuracy) << " | "
        << fixed(m.mean_class_accuracy) << " | " << m.points << " | " << report.scenes.size()
        << " |\n\n"
        << "Class mapping: "
        << (report.request.mapping_path.empty() ? report.class_mapping
                                                : report.request.mapping_path)
        << (report.class_mapping_reason.empty() ? "" : " (" + report.class_mapping_reason + ")")
        << ".\n\n"
        << "| id | class | support | IoU | precision | recall | F1 |\n"
        << "|---:|---|---:|---:|---:|---:|---:|\n";
    for (const auto& c : m.classes) {
      const bool none = c.support == 0;
      out << "| " << c.id << " | " << markdown_cell(c.name) << " | " << c.support << " | "
          << (none ? kNoGroundTruth : fixed(c.iou)) << " | " << fixed(c.precision) << " | "
          << fixed(c.recall) << " | " << (none ? kNoGroundTruth : fixed(c.f1)) << " |\n";
    }
    out << "\nmIoU and mean class accuracy average " << m.classes_averaged << " classes (mean_over "
        << to_string(m.mean_over) << "); – marks a figure that is undefined (docs/metrics.md).\n";
    const std::string note = no_ground_truth_note(m);
    if (!note.empty()) out << '\n' << note << '\n';
    if (report.scenes.size() < 2) return;
    out << "\n## Scenes\n\n"
        << "| scene | points | mIoU | overall accuracy | mean class accuracy | unlabelled |\n"
        << "|---|---:|---:|---:|---:|---:|\n";
    for (const auto& scene : report.scenes) {
      out << "| " << markdown_cell(scene.name) << " | " << scene.metrics.points << " | "
          << fixed(scene.metrics.miou) << " | " << fixed(scene.metrics.overall_accuracy) << " | "
          << fixed(scene.metrics.mean_class_accuracy) << " | " << scene.unlabelled << " |\n";
    }
  });
}

}  // namespace occlusion::job

namespace occlusion {

std::string no_ground_truth_note(const SegmentationMetrics& metrics) {
  std::size_t none = 0;
  bool predicted = false;
  bool averaged = false;
  for (const auto& c : metrics.classes) {
    if (c.support > 0) continue;
    ++none;
    predicted = predicted || c.fp > 0;
    averaged = averaged || c.averaged;
  }
  if (none == 0) return "";
  // The table names them; the note says what their cells mean.
  std::string note = std::string(kNoGroundTruth) + ": " + std::to_string(none) +
                     (none == 1 ? " class has" : " classes have") + " no ground-truth point. ";
  note += predicted ? "Predicted, such a class has IoU and F1 0 (false positives alone), as "
                      "ScanNet's script reports it; never predicted, none"
                    : "Never predicted, such a class has no IoU (0/0; ScanNet's script's nan)";
  note += averaged ? std::string("; mean_over ") + to_string(metrics.mean_over) +
                         " averages it in as 0 (docs/metrics.md)."
                   : std::string("; mean_over ") + to_string(metrics.mean_over) +
                         " leaves it out of the means (docs/metrics.md).";
  return note;
}

}  // namespace occlusion
