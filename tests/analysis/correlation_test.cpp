#include "occlusion/analysis/correlation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace occlusion {
namespace {

// x = 1..5, y = 2 4 5 4 5: by hand, sxy = 6, sxx = 10, syy = 6.
const std::vector<double> kX = {1, 2, 3, 4, 5};
const std::vector<double> kY = {2, 4, 5, 4, 5};

TEST(Correlation, PearsonMatchesTheHandValue) {
  EXPECT_NEAR(*pearson_correlation(kX, kY), 6.0 / std::sqrt(60.0), 1e-12);
  EXPECT_DOUBLE_EQ(*pearson_correlation({1, 2, 3}, {3, 2, 1}), -1.0);
  EXPECT_DOUBLE_EQ(*pearson_correlation({1, 2, 3}, {10, 20, 30}), 1.0);
}

TEST(Correlation, TiesShareTheAverageRank) {
  EXPECT_EQ(average_ranks({10, 20, 20, 30}), (std::vector<double>{1, 2.5, 2.5, 4}));
  EXPECT_EQ(average_ranks({3, 1, 3, 3}), (std::vector<double>{3, 1, 3, 3}));
  EXPECT_EQ(average_ranks({}), std::vector<double>{});
}

TEST(Correlation, SpearmanWithTiesMatchesTheHandValue) {
  // Ranks of y: 1, 2.5, 4.5, 2.5, 4.5; against 1..5: sxy = 7, sxx = 10, syy = 9.
  EXPECT_NEAR(*spearman_correlation(kX, kY), 7.0 / std::sqrt(90.0), 1e-12);
  // Monotone but not linear: Spearman sees a perfect order, Pearson does not.
  const std::vector<double> x = {1, 2, 3, 4}, squares = {1, 4, 9, 16};
  EXPECT_DOUBLE_EQ(*spearman_correlation(x, squares), 1.0);
  EXPECT_LT(*pearson_correlation(x, squares), 1.0);
}

TEST(Correlation, UndefinedForFewerThanThreePairsOrNoVariation) {
  EXPECT_FALSE(pearson_correlation({1, 2}, {1, 2}));
  EXPECT_FALSE(spearman_correlation({1, 2}, {1, 2}));
  EXPECT_FALSE(pearson_correlation({1, 2, 3}, {5, 5, 5}));
  EXPECT_FALSE(spearman_correlation({4, 4, 4}, {1, 2, 3}));
  EXPECT_FALSE(pearson_correlation({}, {}));
}

TEST(Correlation, LeastSquaresLine) {
  const auto fit = least_squares_fit(kX, kY);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->slope, 0.6, 1e-12);
  EXPECT_NEAR(fit->intercept, 2.2, 1e-12);
  EXPECT_FALSE(least_squares_fit({1}, {1}));
  EXPECT_FALSE(least_squares_fit({2, 2}, {1, 3}));
}

TEST(Correlation, CorrelateGathersAll) {
  const Correlation c = correlate(kX, kY);
  EXPECT_EQ(c.n, 5u);
  EXPECT_TRUE(c.pearson && c.spearman && c.fit);
}

TEST(Correlation, RejectsMismatchedOrNonFiniteData) {
  EXPECT_THROW(pearson_correlation({1, 2, 3}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(spearman_correlation({1, 2, NAN}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(least_squares_fit({1, INFINITY}, {1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
