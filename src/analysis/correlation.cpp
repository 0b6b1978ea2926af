#include "occlusion/analysis/correlation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace occlusion {

namespace {

void check(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) {
    throw std::invalid_argument("correlation: " + std::to_string(x.size()) + " x but " +
                                std::to_string(y.size()) + " y values");
  }
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!std::all_of(x.begin(), x.end(), finite) || !std::all_of(y.begin(), y.end(), finite)) {
    throw std::invalid_argument("correlation: a value is not finite");
  }
}

double mean(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

// Centred sums: two passes, so that large offsets (e.g. ranks or heights in
// metres above sea level) do not cancel digits away.
struct Moments {
  double sxx = 0.0, syy = 0.0, sxy = 0.0, mean_x = 0.0, mean_y = 0.0;
};

Moments moments(const std::vector<double>& x, const std::vector<double>& y) {
  Moments m;
  m.mean_x = mean(x);
  m.mean_y = mean(y);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = x[i] - m.mean_x, dy = y[i] - m.mean_y;
    m.sxx += dx * dx;
    m.syy += dy * dy;
    m.sxy += dx * dy;
  }
  return m;
}

}  // namespace

std::optional<double> pearson_correlation(const std::vector<double>& x,
                                          const std::vector<double>& y) {
  check(x, y);
  if (x.size() < 3) return std::nullopt;
  const Moments m = moments(x, y);
  if (m.sxx <= 0.0 || m.syy <= 0.0) return std::nullopt;
  // Rounding may carry |r| a hair past 1 for exactly linear data.
  return std::clamp(m.sxy / std::sqrt(m.sxx * m.syy), -1.0, 1.0);
}

std::vector<double> average_ranks(const std::vector<double>& values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> ranks(values.size());
  for (std::size_t begin = 0; begin < order.size();) {
    std::size_t end = begin + 1;
    while (end < order.size() && values[order[end]] == values[order[begin]]) ++end;
    // Positions begin..end-1 (0-based) share the mean 1-based rank.
    const double rank = 0.5 * static_cast<double>(begin + 1 + end);
    for (std::size_t k = begin; k < end; ++k) ranks[order[k]] = rank;
    begin = end;
  }
  return ranks;
}

std::optional<double> spearman_correlation(const std::vector<double>& x,
                                           const std::vector<double>& y) {
  check(x, y);
  return pearson_correlation(average_ranks(x), average_ranks(y));
}

std::optional<LinearFit> least_squares_fit(const std::vector<double>& x,
                                           const std::vector<double>& y) {
  check(x, y);
  if (x.size() < 2) return std::nullopt;
  const Moments m = moments(x, y);
  if (m.sxx <= 0.0) return std::nullopt;
  LinearFit fit;
  fit.slope = m.sxy / m.sxx;
  fit.intercept = m.mean_y - fit.slope * m.mean_x;
  return fit;
}

Correlation correlate(const std::vector<double>& x, const std::vector<double>& y) {
  Correlation c;
  c.n = x.size();
  c.pearson = pearson_correlation(x, y);
  c.spearman = spearman_correlation(x, y);
  c.fit = least_squares_fit(x, y);
  return c;
}

}  // namespace occlusion
