#include "occlusion/analysis/coverage_matrix.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace occlusion {
namespace {

TEST(CoverageMatrix, WeighsTheTargetsARowSeesAndWhatItWouldAdd) {
  // 130 targets cross two word boundaries; target t weighs t + 1.
  std::vector<double> weight(130);
  for (std::size_t t = 0; t < weight.size(); ++t) weight[t] = static_cast<double>(t + 1);
  CoverageMatrix matrix(2, weight);
  EXPECT_EQ(matrix.words_per_row(), 3u);
  EXPECT_DOUBLE_EQ(matrix.total_weight(), 130.0 * 131.0 / 2.0);
  for (std::size_t t : {0u, 63u, 64u, 129u}) matrix.set_seen(0, t);
  matrix.set_seen(1, 64);
  EXPECT_TRUE(matrix.seen(0, 63));
  EXPECT_FALSE(matrix.seen(1, 63));
  EXPECT_DOUBLE_EQ(matrix.seen_weight(0), 1.0 + 64.0 + 65.0 + 130.0);
  EXPECT_DOUBLE_EQ(matrix.seen_weight(1), 65.0);
  // Candidate 1 already placed: candidate 0 adds all but target 64.
  std::vector<std::uint64_t> covered(matrix.row(1), matrix.row(1) + matrix.words_per_row());
  EXPECT_DOUBLE_EQ(matrix.gain(0, covered), 1.0 + 64.0 + 130.0);
  EXPECT_DOUBLE_EQ(matrix.gain(1, covered), 0.0);
}

TEST(CoverageMatrix, RefusesNegativeOrNonFiniteWeights) {
  EXPECT_THROW(CoverageMatrix(1, {1.0, -1.0}), std::invalid_argument);
  EXPECT_THROW(CoverageMatrix(1, {std::numeric_limits<double>::quiet_NaN()}),
               std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
