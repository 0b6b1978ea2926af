#pragma once
// A confusion matrix over evaluation classes and the segmentation metrics read
// from it. Rows are ground-truth classes, columns predicted classes, plus one
// extra column, "other", for predictions outside the evaluation classes.
//
// What falls outside the classes follows the ScanNet benchmark
// (BenchmarkScripts/3d_evaluation/evaluate_semantic_label.py), so figures are
// comparable with published ones:
//   - a ground truth that is not an evaluation class (the mapping's ignore id,
//     -1 for an unlabelled point, any other id) is skipped: counted in
//     skipped() and nowhere else, so whatever was predicted there is no error;
//   - a prediction that is not an evaluation class (the ignore id, -1 for a
//     point that received no label, an id the network knows but the
//     evaluation does not) goes to the "other" column: a miss (false
//     negative) of the ground-truth class and a false positive of none.
// docs/metrics.md has the formulas and a worked example.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace occlusion {

struct EvaluationClass {
  std::int32_t id = 0;  // in the network's output space, >= 0
  std::string name;

  bool operator==(const EvaluationClass& other) const {
    return id == other.id && name == other.name;
  }
};

class ConfusionMatrix {
 public:
  // No classes: every point is skipped. Useful only as a placeholder.
  ConfusionMatrix() = default;
  // Classes are kept sorted by id. std::invalid_argument for a negative or
  // repeated id.
  explicit ConfusionMatrix(std::vector<EvaluationClass> classes);

  const std::vector<EvaluationClass>& classes() const { return classes_; }
  std::size_t size() const { return classes_.size(); }
  // The column of predictions outside the classes: size().
  std::size_t other_column() const { return classes_.size(); }
  // The row/column of an evaluation id, or nothing when it is not a class.
  std::optional<std::size_t> index_of(std::int32_t id) const;

  // One point (or `count` points) with this ground truth and prediction.
  void add(std::int32_t ground_truth, std::int32_t prediction, std::uint64_t count = 1);
  // Point i has ground_truth[i] and prediction[i]; std::invalid_argument when
  // the sizes differ.
  void add(const std::vector<std::int32_t>& ground_truth,
           const std::vector<std::int32_t>& prediction);

  // Points with ground-truth row `row` predicted as column `column`
  // (other_column() for predictions outside the classes).
  std::uint64_t count(std::size_t row, std::size_t column) const;
  // Points counted in the matrix (ground truth in the classes).
  std::uint64_t total() const;
  // Points skipped because their ground truth is not an evaluation class.
  std::uint64_t skipped() const { return skipped_; }

  // Summing matrices is how several scenes are combined (the standard: a
  // scene weighs by its points, not equally). std::invalid_argument unless
  // both have the same classes.
  ConfusionMatrix& operator+=(const ConfusionMatrix& other);

 private:
  std::vector<EvaluationClass> classes_;
  std::vector<std::int32_t> ids_;      // classes_[i].id, for the lookup
  std::vector<std::uint64_t> counts_;  // size() rows of size() + 1 columns
  std::uint64_t skipped_ = 0;
};

ConfusionMatrix operator+(ConfusionMatrix a, const ConfusionMatrix& b);

// Per class, with tp = count(c, c), fn = row sum - tp (the "other" column
// included), fp = column sum - tp over the class rows.
struct ClassMetrics {
  std::int32_t id = 0;
  std::string name;
  std::uint64_t tp = 0;
  std::uint64_t fp = 0;
  std::uint64_t fn = 0;
  std::uint64_t support = 0;  // ground-truth points of the class: tp + fn
  // tp / (tp + fp + fn); absent when the class has neither ground truth nor
  // predictions: it says nothing about the model, and 0 or 1 would bias the mean.
  std::optional<double> iou;
  std::optional<double> precision;  // tp / (tp + fp); absent with no predictions
  std::optional<double> recall;     // tp / (tp + fn); absent with no support
  // 2 tp / (2 tp + fp + fn), the harmonic mean of precision and recall where
  // both exist; absent exactly when iou is.
  std::optional<double> f1;
  // Whether mIoU and mean class accuracy average this class (MeanOver below).
  bool averaged = false;
};

// Which classes mIoU and mean class accuracy average over. The per-class
// figures are the same under every rule; only the means differ, and only on
// scenes that lack a class (docs/metrics.md, "Averaging rules"):
//   - support:   classes with ground truth (support > 0);
//   - scannet:   classes with ground truth or predictions (tp + fp + fn > 0),
//                as ScanNet's evaluate_semantic_label.py, whose get_iou is NaN
//                only for 0/0: a class predicted but absent adds an IoU of 0
//                (and a class accuracy of 0);
//   - pointcept: every evaluation class, an undefined IoU or accuracy counting
//                0, as Pointcept's intersection / (union + 1e-10) averaged
//                with np.mean.
enum class MeanOver { support, scannet, pointcept };

const char* to_string(MeanOver rule);
// "support", "scannet" or "pointcept"; nothing for any other text.
std::optional<MeanOver> parse_mean_over(const std::string& text);

struct SegmentationMetrics {
  std::vector<ClassMetrics> classes;  // one per evaluation class, by id
  MeanOver mean_over = MeanOver::support;
  // Mean IoU over the classes the rule averages; absent when there are none.
  std::optional<double> miou;
  // Σ tp / points; absent when no point was counted.
  std::optional<double> overall_accuracy;
  // Mean recall over the same classes as miou.
  std::optional<double> mean_class_accuracy;
  std::size_t classes_with_support = 0;
  std::size_t classes_averaged = 0;  // how many classes the means are over
  std::uint64_t points = 0;          // counted in the matrix (ConfusionMatrix::total)
  std::uint64_t correct = 0;         // Σ tp
  std::uint64_t other = 0;           // predictions outside the classes (all misses)
  std::uint64_t skipped = 0;         // ground truth outside the classes
};

SegmentationMetrics compute_metrics(const ConfusionMatrix& matrix,
                                    MeanOver mean_over = MeanOver::support);

}  // namespace occlusion
