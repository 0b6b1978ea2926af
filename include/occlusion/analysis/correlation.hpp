#pragma once
// How strongly two measures go together over paired samples, for the
// occlusion study (does mIoU fall as occlusion rises?). Pure standard C++.
//
// Undefined (nullopt) rather than 0 or NaN where the data cannot say: fewer
// than three pairs (two points always lie on a line, so |r| = 1 says nothing)
// or a measure that does not vary.

#include <cstddef>
#include <optional>
#include <vector>

namespace occlusion {

// Pearson's r: covariance over the product of the standard deviations.
// std::invalid_argument when x and y differ in size or hold a non-finite value.
std::optional<double> pearson_correlation(const std::vector<double>& x,
                                          const std::vector<double>& y);

// Spearman's rho: Pearson's r of the ranks, tied values sharing the mean of
// the ranks they span (so it stays exact with ties). Same errors.
std::optional<double> spearman_correlation(const std::vector<double>& x,
                                           const std::vector<double>& y);

// 1-based ranks; equal values get the average of their positions:
// {10, 20, 20, 30} -> {1, 2.5, 2.5, 4}.
std::vector<double> average_ranks(const std::vector<double>& values);

struct LinearFit {
  double slope = 0.0;
  double intercept = 0.0;
};

// Least squares y = slope x + intercept; nullopt for fewer than two pairs or
// x that does not vary. Same errors.
std::optional<LinearFit> least_squares_fit(const std::vector<double>& x,
                                           const std::vector<double>& y);

// The three figures the study reports for each measure against mIoU.
struct Correlation {
  std::size_t n = 0;
  std::optional<double> pearson;
  std::optional<double> spearman;
  std::optional<LinearFit> fit;
};
Correlation correlate(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace occlusion
