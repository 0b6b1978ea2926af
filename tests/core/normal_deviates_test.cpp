// The ziggurat's deviates against the standard normal's own figures: the
// first deviate of each of two million streams (as the virtual scanner draws
// one per beam) has mean 0, sigma 1, no skew, kurtosis 3, the tail shares
// erfc gives, the density of every bin a tenth of a sigma wide (the wedges
// and the tail are where a ziggurat goes wrong), and no correlation between
// neighbouring streams or along one stream.

#include "occlusion/core/normal_deviates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace occlusion {
namespace {

constexpr std::size_t kDraws = std::size_t{1} << 21;

// The first deviate of streams 0 .. kDraws - 1 of seed 7.
const std::vector<double>& first_deviates() {
  static const std::vector<double> values = [] {
    std::vector<double> v(kDraws);
    for (std::size_t i = 0; i < kDraws; ++i) v[i] = NormalDeviates(7, i).next();
    return v;
  }();
  return values;
}

// P(Z <= x) for a standard normal Z.
double normal_cdf(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

TEST(NormalDeviates, MomentsAreTheStandardNormals) {
  const std::vector<double>& v = first_deviates();
  double sum = 0.0, sum2 = 0.0, sum3 = 0.0, sum4 = 0.0;
  for (const double x : v) {
    sum += x;
    sum2 += x * x;
    sum3 += x * x * x;
    sum4 += x * x * x * x;
  }
  const double n = static_cast<double>(v.size());
  // Five standard errors: 1/sqrt(n), sqrt(2/n), sqrt(6/n), sqrt(96/n) for mean,
  // variance, skewness and kurtosis of N(0, 1).
  EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 5.0 * std::sqrt(2.0 / n));
  EXPECT_NEAR(sum3 / n, 0.0, 5.0 * std::sqrt(6.0 / n));
  EXPECT_NEAR(sum4 / n, 3.0, 5.0 * std::sqrt(96.0 / n));
}

TEST(NormalDeviates, TailsHoldTheShareErfcGives) {
  const std::vector<double>& v = first_deviates();
  const double n = static_cast<double>(v.size());
  // 3.6541528853610088 is where the ziggurat's tail algorithm takes over.
  for (const double k : {1.0, 2.0, 3.0, 3.6541528853610088, 4.0, 4.5}) {
    std::size_t beyond = 0, below = 0;
    for (const double x : v) {
      beyond += x > k ? 1 : 0;
      below += x < -k ? 1 : 0;
    }
    const double p = 0.5 * std::erfc(k / std::sqrt(2.0));
    const double tolerance = 5.0 * std::sqrt(n * p * (1.0 - p)) + 1.0;
    EXPECT_NEAR(static_cast<double>(beyond), n * p, tolerance) << "x > " << k;
    EXPECT_NEAR(static_cast<double>(below), n * p, tolerance) << "x < -" << k;
  }
}

TEST(NormalDeviates, EveryTenthOfASigmaHoldsTheDensitysShare) {
  const std::vector<double>& v = first_deviates();
  constexpr int kBins = 80;  // [-4, 4) in steps of 0.1, and the two tails beyond
  std::vector<double> observed(kBins + 2, 0.0);
  for (const double x : v) {
    const double bin = std::floor((x + 4.0) * 10.0);
    observed[bin < 0.0 ? 0 : bin >= kBins ? kBins + 1 : static_cast<std::size_t>(bin) + 1] += 1.0;
  }
  const double n = static_cast<double>(v.size());
  double chi_square = 0.0;
  for (int b = 0; b < kBins + 2; ++b) {
    const double lo = b == 0 ? -INFINITY : -4.0 + 0.1 * (b - 1);
    const double hi = b == kBins + 1 ? INFINITY : -4.0 + 0.1 * b;
    const double expected = n * (normal_cdf(hi) - normal_cdf(lo));
    chi_square += (observed[b] - expected) * (observed[b] - expected) / expected;
    EXPECT_NEAR(observed[b], expected, 5.0 * std::sqrt(expected) + 1.0)
        << "[" << lo << ", " << hi << ")";
  }
  // 81 degrees of freedom: mean 81, sigma 12.7; this is five sigmas above.
  EXPECT_LT(chi_square, 145.0);
}

TEST(NormalDeviates, NeighbouringStreamsAndSuccessiveDrawsAreUncorrelated) {
  const std::vector<double>& v = first_deviates();
  double across = 0.0;
  for (std::size_t i = 1; i < v.size(); ++i) across += v[i - 1] * v[i];
  NormalDeviates stream(7, 12345);
  double previous = stream.next(), along = 0.0;
  for (std::size_t i = 1; i < kDraws; ++i) {
    const double x = stream.next();
    along += previous * x;
    previous = x;
  }
  const double n = static_cast<double>(kDraws);
  EXPECT_NEAR(across / n, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(along / n, 0.0, 5.0 / std::sqrt(n));
}

TEST(NormalDeviates, ASeedAndStreamGiveOneSequence) {
  NormalDeviates a(3, 9), b(3, 9), other_seed(4, 9), other_stream(3, 10);
  for (int i = 0; i < 1000; ++i) {
    const double x = a.next();
    ASSERT_EQ(x, b.next()) << i;
    EXPECT_NE(x, other_seed.next()) << i;
    EXPECT_NE(x, other_stream.next()) << i;
  }
}

}  // namespace
}  // namespace occlusion
