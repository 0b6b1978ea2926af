#include "occlusion/analysis/confusion_matrix.hpp"

#include <algorithm>
#include <stdexcept>

namespace occlusion {

ConfusionMatrix::ConfusionMatrix(std::vector<EvaluationClass> classes)
    : classes_(std::move(classes)) {
  std::sort(classes_.begin(), classes_.end(),
            [](const EvaluationClass& a, const EvaluationClass& b) { return a.id < b.id; });
  for (std::size_t i = 0; i < classes_.size(); ++i) {
    const std::int32_t id = classes_[i].id;
    // Negative ids are the "no label" of predictions (-1) and ignore ids like
    // MinkowskiEngine's -100; letting a class use one would make it count.
    if (id < 0) {
      throw std::invalid_argument("ConfusionMatrix: class id " + std::to_string(id) +
                                  " is negative");
    }
    if (i > 0 && classes_[i - 1].id == id) {
      throw std::invalid_argument("ConfusionMatrix: class id " + std::to_string(id) +
                                  " given twice");
    }
    ids_.push_back(id);
  }
  counts_.assign(classes_.size() * (classes_.size() + 1), 0);
}

std::optional<std::size_t> ConfusionMatrix::index_of(std::int32_t id) const {
  const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
  if (it == ids_.end() || *it != id) return std::nullopt;
  return static_cast<std::size_t>(it - ids_.begin());
}

void ConfusionMatrix::add(std::int32_t ground_truth, std::int32_t prediction, std::uint64_t count) {
  const auto row = index_of(ground_truth);
  if (!row) {
    skipped_ += count;
    return;
  }
  const std::size_t column = index_of(prediction).value_or(other_column());
  counts_[*row * (size() + 1) + column] += count;
}

void ConfusionMatrix::add(const std::vector<std::int32_t>& ground_truth,
                          const std::vector<std::int32_t>& prediction) {
  if (ground_truth.size() != prediction.size()) {
    throw std::invalid_argument("ConfusionMatrix: " + std::to_string(ground_truth.size()) +
                                " ground-truth labels but " + std::to_string(prediction.size()) +
                                " predictions");
  }
  for (std::size_t i = 0; i < ground_truth.size(); ++i) add(ground_truth[i], prediction[i]);
}

std::uint64_t ConfusionMatrix::count(std::size_t row, std::size_t column) const {
  if (row >= size() || column > size()) {
    throw std::out_of_range("ConfusionMatrix: cell (" + std::to_string(row) + ", " +
                            std::to_string(column) + ") outside a " + std::to_string(size()) +
                            "-class matrix");
  }
  return counts_[row * (size() + 1) + column];
}

std::uint64_t ConfusionMatrix::total() const {
  std::uint64_t sum = 0;
  for (const auto c : counts_) sum += c;
  return sum;
}

ConfusionMatrix& ConfusionMatrix::operator+=(const ConfusionMatrix& other) {
  if (classes_ != other.classes_) {
    throw std::invalid_argument("ConfusionMatrix: cannot add matrices over different classes");
  }
  for (std::size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
  skipped_ += other.skipped_;
  return *this;
}

ConfusionMatrix operator+(ConfusionMatrix a, const ConfusionMatrix& b) {
  a += b;
  return a;
}

namespace {

std::optional<double> ratio(std::uint64_t numerator, std::uint64_t denominator) {
  if (denominator == 0) return std::nullopt;
  return static_cast<double>(numerator) / static_cast<double>(denominator);
}

ClassMetrics class_metrics(const ConfusionMatrix& matrix, std::size_t c) {
  ClassMetrics m;
  m.id = matrix.classes()[c].id;
  m.name = matrix.classes()[c].name;
  m.tp = matrix.count(c, c);
  for (std::size_t column = 0; column <= matrix.size(); ++column) {
    if (column != c) m.fn += matrix.count(c, column);
  }
  for (std::size_t row = 0; row < matrix.size(); ++row) {
    if (row != c) m.fp += matrix.count(row, c);
  }
  m.support = m.tp + m.fn;
  m.iou = ratio(m.tp, m.tp + m.fp + m.fn);
  m.precision = ratio(m.tp, m.tp + m.fp);
  m.recall = ratio(m.tp, m.support);
  m.f1 = ratio(2 * m.tp, 2 * m.tp + m.fp + m.fn);
  return m;
}

// Whether `rule` averages class m in, and so counts an undefined figure as 0.
bool averaged(const ClassMetrics& m, MeanOver rule) {
  switch (rule) {
    case MeanOver::support:
      return m.support > 0;
    case MeanOver::scannet:
      return m.iou.has_value();
    case MeanOver::pointcept:
      return true;
  }
  return false;
}

}  // namespace

const char* to_string(MeanOver rule) {
  switch (rule) {
    case MeanOver::support:
      return "support";
    case MeanOver::scannet:
      return "scannet";
    case MeanOver::pointcept:
      return "pointcept";
  }
  return "support";
}

std::optional<MeanOver> parse_mean_over(const std::string& text) {
  for (const MeanOver rule : {MeanOver::support, MeanOver::scannet, MeanOver::pointcept}) {
    if (text == to_string(rule)) return rule;
  }
  return std::nullopt;
}

SegmentationMetrics compute_metrics(const ConfusionMatrix& matrix, MeanOver mean_over) {
  SegmentationMetrics metrics;
  metrics.mean_over = mean_over;
  metrics.points = matrix.total();
  metrics.skipped = matrix.skipped();
  double iou_sum = 0.0;
  double recall_sum = 0.0;
  for (std::size_t c = 0; c < matrix.size(); ++c) {
    ClassMetrics m = class_metrics(matrix, c);
    metrics.correct += m.tp;
    metrics.other += matrix.count(c, matrix.other_column());
    if (m.support > 0) ++metrics.classes_with_support;
    m.averaged = averaged(m, mean_over);
    if (m.averaged) {
      ++metrics.classes_averaged;
      iou_sum += m.iou.value_or(0.0);
      recall_sum += m.recall.value_or(0.0);
    }
    metrics.classes.push_back(std::move(m));
  }
  if (metrics.classes_averaged > 0) {
    const auto n = static_cast<double>(metrics.classes_averaged);
    metrics.miou = iou_sum / n;
    metrics.mean_class_accuracy = recall_sum / n;
  }
  metrics.overall_accuracy = ratio(metrics.correct, metrics.points);
  return metrics;
}

}  // namespace occlusion
