#include <gtest/gtest.h>

#include <cmath>

#include "occlusion/analysis/viewpoints.hpp"

namespace occlusion {
namespace {

const Eigen::Vector3d kLo(-1, 2, 0), kHi(9, 7, 3);

TEST(GridViewpoints, NineMakeAThreeByThreeGridAtMidHeight) {
  const auto points = grid_viewpoints(9, kLo, kHi);
  ASSERT_EQ(points.size(), 9u);
  // Cell centres of a 3 x 3 grid over x in [0, 8], y in [2.5, 6.5].
  const double xs[3] = {0 + 8.0 / 6, 4, 8 - 8.0 / 6};
  const double ys[3] = {2.5 + 4.0 / 6, 4.5, 6.5 - 4.0 / 6};
  for (std::size_t k = 0; k < 9; ++k) {
    EXPECT_NEAR(points[k].x(), xs[k % 3], 1e-12) << k;
    EXPECT_NEAR(points[k].y(), ys[k / 3], 1e-12) << k;  // row by row
    EXPECT_EQ(points[k].z(), 1.5);
  }
}

TEST(GridViewpoints, OneIsTheCentre) {
  const auto points = grid_viewpoints(1, kLo, kHi);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_TRUE(points[0].isApprox(0.5 * (kLo + kHi)));
}

TEST(GridViewpoints, AnyCountFitsDistinctInsideTheMiddleOfTheBox) {
  for (std::size_t count : {2u, 3u, 5u, 7u, 10u, 16u, 17u, 50u}) {
    const auto points = grid_viewpoints(count, kLo, kHi);
    ASSERT_EQ(points.size(), count);
    const auto columns = static_cast<std::size_t>(std::ceil(std::sqrt(double(count))));
    for (std::size_t k = 0; k < count; ++k) {
      EXPECT_GT(points[k].x(), kLo.x() + 1.0 - 1e-12);  // 10% of 10 m
      EXPECT_LT(points[k].x(), kHi.x() - 1.0 + 1e-12);
      EXPECT_GT(points[k].y(), kLo.y() + 0.5 - 1e-12);
      EXPECT_LT(points[k].y(), kHi.y() - 0.5 + 1e-12);
      EXPECT_EQ(points[k].z(), 1.5);
      for (std::size_t m = 0; m < k; ++m) EXPECT_FALSE(points[k].isApprox(points[m])) << count;
      if (k > 0 && k % columns != 0) {
        EXPECT_GT(points[k].x(), points[k - 1].x());
      }
    }
    EXPECT_EQ(grid_viewpoints(count, kLo, kHi), points);  // reproducible
  }
}

TEST(GridViewpoints, RejectsNoViewpointsAndEmptyBoxes) {
  EXPECT_THROW(grid_viewpoints(0, kLo, kHi), std::invalid_argument);
  EXPECT_THROW(grid_viewpoints(4, kHi, kLo), std::invalid_argument);
  EXPECT_THROW(grid_viewpoints(4, kLo, {NAN, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
