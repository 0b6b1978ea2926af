// The shared quantile selection against a full sort: several ranks of one
// array, in any order, give exactly the sorted array's values there.

#include "quantiles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace occlusion {
namespace {

TEST(Quantiles, RanksInAnyOrderAreTheSortedValues) {
  std::mt19937 random(7);
  for (const std::size_t n : {1u, 2u, 3u, 10u, 1001u, 20000u}) {
    std::vector<float> values(n);
    // Few distinct values: ties everywhere.
    std::uniform_int_distribution<int> pick(0, static_cast<int>(n / 3 + 1));
    for (float& v : values) v = static_cast<float>(pick(random)) * 0.5f;
    std::vector<float> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    const std::vector<std::size_t> ranks = {n / 2, n / 10, n - 1, 0, n / 2, (9 * n) / 10, n / 3};
    std::vector<float> work = values;
    const std::vector<float> got = quantiles::at_ranks(work, ranks);
    ASSERT_EQ(got.size(), ranks.size());
    for (std::size_t r = 0; r < ranks.size(); ++r) {
      EXPECT_EQ(got[r], sorted[ranks[r]]) << "n " << n << " rank " << ranks[r];
    }
    std::sort(work.begin(), work.end());
    EXPECT_EQ(work, sorted) << "the values are only reordered";
  }
}

TEST(Quantiles, ARankIsTheRoundedShareOfTheLastIndex) {
  // 11 values 0..10: q 0.1 is rank 1, the median rank 5, q 0.9 rank 9; 0.25
  // of 10 is 2.5, rounded up to 3.
  std::vector<double> values = {10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0};
  const std::vector<double> got = quantiles::in_place(values, {0.5, 0.1, 0.9, 0.25});
  EXPECT_EQ(got, (std::vector<double>{5, 1, 9, 3}));
  std::vector<double> again = {10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0};
  EXPECT_EQ(quantiles::at(again, 0.25), 3.0);
  std::vector<double> none;
  EXPECT_EQ(quantiles::at(none, 0.5), 0.0);
}

}  // namespace
}  // namespace occlusion
