#include <algorithm>
#include <cstdio>
#include <string>

#include "arguments.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "option_table.hpp"
#include "run_command.hpp"

namespace occlusion::cli {

namespace {

struct EvaluateCommand {
  EvaluateRequest request;
  OutputOptions output;
  bool confusion = false;
};

EvaluateCommand parse(const std::vector<std::string>& args) {
  EvaluateCommand command;
  EvaluateRequest& request = command.request;
  if (const auto config = config_path(args)) apply_config(load_config(*config), request);

  OptionTable table("-eval");
  add_output_options(table, command.output);
  add_threads_option(table, request.threads);
  bool predictions_given = false;
  bool ground_truth_given = false;
  table.value({"--prediction", "--predictions"}, [&](const std::string&, const std::string& v) {
    add_to_list(request.predictions, predictions_given, v);
  });
  table.value({"--mapping-path", "--mapping"},
              [&](const std::string&, const std::string& v) { request.mapping_path = v; });
  table.value({"--ignored-classes"}, [&](const std::string&, const std::string& v) {
    request.ignored_classes = split_list(v);
  });
  table.value({"--max-distance"}, [&](const std::string& option, const std::string& v) {
    request.max_distance = parse_number(option, v);
  });
  table.flag({"--skip-bad-lines"}, [&] { request.skip_bad_lines = true; });
  table.flag({"--confusion"}, [&] { command.confusion = true; });
  table.value({"--out"}, [&](const std::string&, const std::string& v) { request.out = v; });
  table.parse(args, [&](const std::string& v) {
    add_to_list(request.ground_truth, ground_truth_given, v);
  });
  return command;
}

void print_help() {
  std::printf(
      "usage: occlusion -eval GT [GT2 ...] --prediction PRED [--prediction PRED2 ...] "
      "[options]\n"
      "\n"
      "Semantic segmentation quality against labelled ground truth. Each ground truth GT\n"
      "(a labelled cloud with class names: PLY/PCD written by occlusion, an S3DIS room or\n"
      "Area) is paired with the --prediction given in the same position. A prediction is\n"
      "a label file (one integer per line, one line per ground-truth point, in order;\n"
      ".labels, .label, or a one-column .txt) or a labelled cloud. Predicted labels are\n"
      "evaluation ids (the network's output space); ground-truth classes are mapped to\n"
      "them by name (default: the seed's table 3.1). A prediction cloud with other points\n"
      "(a voxelised output) gives each ground-truth point the label of its nearest\n"
      "predicted point within --max-distance; points farther away count as misses.\n"
      "The scenes' confusion matrices are summed; per-scene figures are kept.\n"
      "\n"
      "options (each is also a key of the config section occlusion.evaluate; GT is\n"
      "ground_truth, --prediction is predictions):\n"
      "  --config FILE              JSON config; options on the command line override it\n"
      "  --prediction PRED          the prediction for the next ground truth (repeatable)\n"
      "  --mapping-path FILE        class mapping JSON (docs/metrics.md; alias --mapping)\n"
      "  --ignored-classes A,B,...  ground-truth classes to skip, on top of the mapping's\n"
      "  --max-distance D           nearest-neighbour limit in scene units (default 0.05;\n"
      "                             0: predictions must be on the ground truth's points)\n"
      "  --skip-bad-lines           skip (and count) malformed lines of text clouds\n"
      "  --threads N                worker threads (default 0 = all cores)\n"
      "  --out DIR                  write GT.eval.json, .csv (per class) and .md (a table);\n"
      "                             with several scenes eval.json, eval.csv, eval.md\n"
      "  --confusion                print the confusion matrix (the JSON always has it)\n"
      "  --json                     print one JSON object (headline: miou)\n"
      "  -q, --quiet                no progress on stderr\n"
      "\n"
      "Counting follows the ScanNet benchmark: ground truth outside the evaluation\n"
      "classes is skipped; a prediction outside them is a miss of the true class, no\n"
      "class's false positive; a class with neither ground truth nor predictions has no\n"
      "IoU. Averaging (mean_over) is our own rule by default: mIoU and mean class\n"
      "accuracy average the classes that have ground truth ('support'). ScanNet's\n"
      "script also averages in a 0 for a class predicted but absent ('scannet');\n"
      "Pointcept averages every class, 0 where undefined ('pointcept'). The JSON's\n"
      "mean_over says which rule; docs/metrics.md has all three.\n");
}

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
  std::printf("  mIoU %s   overall accuracy %s   mean class accuracy %s\n", figure(m.miou).c_str(),
              figure(m.overall_accuracy).c_str(), figure(m.mean_class_accuracy).c_str());
  std::printf("  %llu points evaluated, %llu skipped (ground truth ignored), %zu unlabelled\n",
              static_cast<unsigned long long>(m.points), static_cast<unsigned long long>(m.skipped),
              unlabelled);
  std::printf("    %-16s %4s %10s %8s %9s %8s %8s\n", "class", "id", "support", "IoU", "precision",
              "recall", "F1");
  for (const auto& c : m.classes) {
    std::printf("    %-16s %4d %10llu %8s %9s %8s %8s\n", c.name.c_str(), c.id,
                static_cast<unsigned long long>(c.support), figure(c.iou).c_str(),
                figure(c.precision).c_str(), figure(c.recall).c_str(), figure(c.f1).c_str());
  }
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

int run_evaluate_command(const std::vector<std::string>& args) {
  const EvaluateCommand command = parse(args);
  return run_command<EvaluateReport>(
      command.output, "eval", print_help,
      [&](const Progress& progress) { return run_evaluate(command.request, progress); },
      [&](const EvaluateReport& report) { print_human(report, command.confusion); });
}

}  // namespace occlusion::cli
