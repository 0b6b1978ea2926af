#include "occlusion/core/polygon_fan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace occlusion {
namespace {

// The L [0,2]x[0,1] plus [0,1]x[1,2], counter-clockwise. By hand: the 2 x 1
// bar has area 2 and centroid (1, 1/2), the 1 x 1 square on it area 1 and
// centroid (1/2, 3/2), so the L has area 3 and centroid (5/6, 5/6).
const std::vector<Eigen::Vector2d> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

std::vector<Eigen::Vector2d> shifted(std::vector<Eigen::Vector2d> polygon,
                                     const Eigen::Vector2d& by) {
  for (auto& p : polygon) p += by;
  return polygon;
}

TEST(PolygonFan, SquareCentroidIsItsCentre) {
  const std::vector<Eigen::Vector2d> square = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  EXPECT_EQ(polygon_centroid_2d(square), Eigen::Vector2d(2, 2));
  EXPECT_EQ(polygon_signed_area(square), 4.0);
}

TEST(PolygonFan, LCentroidMatchesTheHandComputation) {
  const Eigen::Vector2d centroid = polygon_centroid_2d(kL);
  EXPECT_NEAR(centroid.x(), 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(centroid.y(), 5.0 / 6.0, 1e-15);
  EXPECT_DOUBLE_EQ(polygon_signed_area(kL), 3.0);
}

TEST(PolygonFan, WindingOnlyFlipsTheAreaSign) {
  std::vector<Eigen::Vector2d> clockwise(kL.rbegin(), kL.rend());
  EXPECT_DOUBLE_EQ(polygon_signed_area(clockwise), -3.0);
  const Eigen::Vector2d centroid = polygon_centroid_2d(clockwise);
  EXPECT_NEAR(centroid.x(), 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(centroid.y(), 5.0 / 6.0, 1e-15);
}

TEST(PolygonFan, CentroidIsNotTheVertexMean) {
  // A triangle's centroid is its vertex mean, but an extra vertex near a
  // corner moves the mean and leaves the area centroid where it was.
  const std::vector<Eigen::Vector2d> triangle = {{0, 0}, {3, 0}, {0, 3}};
  const std::vector<Eigen::Vector2d> crowded = {{0, 0}, {2.999, 0}, {3, 0}, {0, 3}};
  EXPECT_TRUE(polygon_centroid_2d(triangle).isApprox(Eigen::Vector2d(1, 1), 1e-15));
  EXPECT_NEAR(polygon_centroid_2d(crowded).x(), 1.0, 1e-12);
}

TEST(PolygonFan, FarFromTheOriginKeepsItsPrecision) {
  // Raw shoelace sums of coordinates near 1e7 lose about 7 digits; summing
  // relative to the first vertex does not.
  const Eigen::Vector2d far(1e7, -3e7);
  const Eigen::Vector2d centroid = polygon_centroid_2d(shifted(kL, far)) - far;
  EXPECT_NEAR(centroid.x(), 5.0 / 6.0, 1e-8);
  EXPECT_NEAR(centroid.y(), 5.0 / 6.0, 1e-8);
  EXPECT_NEAR(polygon_signed_area(shifted(kL, far)), 3.0, 1e-8);
}

TEST(PolygonFan, DegeneratePolygonsAreRejected) {
  EXPECT_THROW(polygon_centroid_2d({{0, 0}, {1, 0}}), std::invalid_argument);
  EXPECT_THROW(polygon_centroid_2d({{0, 0}, {1, 1}, {2, 2}}), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(polygon_centroid_2d({{0, 0}, {1, 0}, {nan, 1}}), std::invalid_argument);
  EXPECT_EQ(polygon_signed_area({{0, 0}, {1, 0}}), 0.0);
}

TEST(PolygonFan, FanCoversThePolygonWithItsWinding) {
  const auto fan = fan_triangles(10, 4, 4);
  ASSERT_EQ(fan.size(), 4u);
  EXPECT_EQ(fan[0], (std::array<std::uint32_t, 3>{10, 4, 5}));
  EXPECT_EQ(fan[3], (std::array<std::uint32_t, 3>{10, 7, 4}));
  EXPECT_THROW(fan_triangles(0, 1, 2), std::invalid_argument);

  // The L is not convex, but it is star-shaped from its centroid: the fan's
  // triangles all keep its counter-clockwise winding and add up to its area.
  std::vector<Eigen::Vector2d> points = kL;
  points.push_back(polygon_centroid_2d(kL));
  double area = 0.0;
  for (const auto& t : fan_triangles(6, 0, kL.size())) {
    const double part = polygon_signed_area({points[t[0]], points[t[1]], points[t[2]]});
    EXPECT_GT(part, 0.0);
    area += part;
  }
  EXPECT_NEAR(area, 3.0, 1e-12);
}

}  // namespace
}  // namespace occlusion
