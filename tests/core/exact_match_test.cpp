#include "occlusion/core/exact_match.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

namespace occlusion {
namespace {

using Points = std::vector<Eigen::Vector3f>;

TEST(ExactMatch, RecoversAShuffle) {
  Points source;
  for (int i = 0; i < 1000; ++i) {
    source.emplace_back(static_cast<float>(i % 10), static_cast<float>(i / 10 % 10),
                        static_cast<float>(i / 100) * 0.1f);
  }
  std::vector<std::size_t> permutation(source.size());
  std::iota(permutation.begin(), permutation.end(), std::size_t{0});
  std::shuffle(permutation.begin(), permutation.end(), std::mt19937(7));
  Points target;
  for (const auto k : permutation) target.push_back(source[k]);

  const ExactMatch match = match_exact_points(source, target);
  EXPECT_TRUE(match.complete());
  EXPECT_EQ(match.source_of, permutation);
}

TEST(ExactMatch, DuplicatesPairInOrderOfAppearance) {
  const Points source{{1, 1, 1}, {0, 0, 0}, {1, 1, 1}};
  const Points target{{1, 1, 1}, {1, 1, 1}, {0, 0, 0}};
  const ExactMatch match = match_exact_points(source, target);
  EXPECT_TRUE(match.complete());
  EXPECT_EQ(match.source_of, (std::vector<std::size_t>{0, 2, 1}));
}

TEST(ExactMatch, ReportsPointsWithoutPartner) {
  // One more duplicate in the target than the source has, and a point the
  // source lacks; the source's (5,5,5) is left over.
  const Points source{{1, 1, 1}, {5, 5, 5}, {2, 2, 2}};
  const Points target{{2, 2, 2}, {1, 1, 1}, {3, 3, 3}, {1, 1, 1}};
  const ExactMatch match = match_exact_points(source, target);
  EXPECT_FALSE(match.complete());
  EXPECT_EQ(match.unmatched_targets, 2u);
  EXPECT_EQ(match.first_unmatched_target, 2u);
  EXPECT_EQ(match.unmatched_sources, 1u);
  EXPECT_EQ(match.source_of[0], 2u);
  EXPECT_EQ(match.source_of[1], 0u);
  EXPECT_EQ(match.source_of[3], ExactMatch::kNone);
}

TEST(ExactMatch, NoToleranceForNearlyEqualPoints) {
  const Points source{{1.0f, 2.0f, 3.0f}};
  const Points target{{1.0f, 2.0f, std::nextafter(3.0f, 4.0f)}};
  EXPECT_FALSE(match_exact_points(source, target).complete());
  EXPECT_TRUE(match_exact_points({}, {}).complete());
}

// Issue 44, 2.6: NaN compared as equal to every point, so a NaN point took
// the place of a real one in the pairing.
TEST(ExactMatch, APointWithANonFiniteCoordinatePairsWithNone) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Points source{{nan, nan, nan}, {1, 1, 1}, {0, 0, 0}, {0, inf, 0}};
  const Points target{{0, 0, 0}, {1, 1, 1}, {nan, 0, 0}};
  const ExactMatch match = match_exact_points(source, target);
  EXPECT_FALSE(match.complete());
  EXPECT_EQ(match.source_of, (std::vector<std::size_t>{2, 1, ExactMatch::kNone}));
  EXPECT_EQ(match.unmatched_targets, 1u);
  EXPECT_EQ(match.first_unmatched_target, 2u);
  EXPECT_EQ(match.unmatched_sources, 2u);
}

}  // namespace
}  // namespace occlusion
