#include "occlusion/core/triangle.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace occlusion {
namespace {

const Triangle kUnit{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

Ray down_from(float x, float y) {
  return Ray{{x, y, 1}, {0, 0, -1}};
}

TEST(Triangle, HitsInteriorAtKnownT) {
  const auto t = intersect_triangle(down_from(0.25f, 0.25f), kUnit);
  ASSERT_TRUE(t);
  EXPECT_FLOAT_EQ(*t, 1.0f);
}

TEST(Triangle, MissesOutside) {
  EXPECT_FALSE(intersect_triangle(down_from(0.6f, 0.6f), kUnit));
  EXPECT_FALSE(intersect_triangle(down_from(-0.01f, 0.5f), kUnit));
}

TEST(Triangle, EdgesAndVerticesAreClosed) {
  EXPECT_TRUE(intersect_triangle(down_from(0.5f, 0.0f), kUnit));  // on edge v0-v1
  EXPECT_TRUE(intersect_triangle(down_from(0.5f, 0.5f), kUnit));  // on the hypotenuse
  EXPECT_TRUE(intersect_triangle(down_from(0.0f, 0.0f), kUnit));  // vertex v0
  EXPECT_TRUE(intersect_triangle(down_from(1.0f, 0.0f), kUnit));  // vertex v1
  EXPECT_TRUE(intersect_triangle(down_from(0.0f, 1.0f), kUnit));  // vertex v2
}

TEST(Triangle, IntervalIsClosedAtBothEnds) {
  Ray ray = down_from(0.25f, 0.25f);  // hit at t = 1
  ray.t_max = 1.0f;
  EXPECT_TRUE(intersect_triangle(ray, kUnit));
  ray.t_max = std::nextafter(1.0f, 0.0f);
  EXPECT_FALSE(intersect_triangle(ray, kUnit));
  ray.t_max = 2.0f;
  ray.t_min = 1.0f;
  EXPECT_TRUE(intersect_triangle(ray, kUnit));
  ray.t_min = std::nextafter(1.0f, 2.0f);
  EXPECT_FALSE(intersect_triangle(ray, kUnit));
}

TEST(Triangle, BehindTheOriginMisses) {
  const Ray up{{0.25f, 0.25f, 1.0f}, {0, 0, 1}};
  EXPECT_FALSE(intersect_triangle(up, kUnit));
}

TEST(Triangle, ParallelRaysMissEvenInThePlane) {
  // In the plane, crossing the triangle.
  EXPECT_FALSE(intersect_triangle(Ray{{-1, 0.25f, 0}, {1, 0, 0}}, kUnit));
  // Above the plane.
  EXPECT_FALSE(intersect_triangle(Ray{{-1, 0.25f, 0.5f}, {1, 0, 0}}, kUnit));
  // In the plane of a tilted triangle, along a non-axis direction.
  const Triangle tilted{{0, 0, 0}, {1, 0, 1}, {0, 1, 1}};
  const Eigen::Vector3f in_plane = Eigen::Vector3f(1, 0, 1) - Eigen::Vector3f(0, 1, 1);
  EXPECT_FALSE(intersect_triangle(Ray{{0.1f, 0.6f, 0.7f}, in_plane}, tilted));
}

TEST(Triangle, BothFacesAreHit) {
  const Ray from_below{{0.25f, 0.25f, -1.0f}, {0, 0, 1}};
  EXPECT_TRUE(intersect_triangle(from_below, kUnit));
}

TEST(Triangle, DegenerateTrianglesAreNeverHit) {
  const Triangle collinear{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const Triangle point{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  EXPECT_FALSE(intersect_triangle(down_from(1.0f, 0.0f), collinear));
  EXPECT_FALSE(intersect_triangle(Ray{{0, 1, 0}, {0, -1, 0}}, collinear));
  EXPECT_FALSE(intersect_triangle(down_from(0.0f, 0.0f), point));
  EXPECT_DOUBLE_EQ(collinear.area(), 0.0);
}

TEST(Triangle, UnnormalisedDirectionScalesT) {
  const Ray ray{{0.25f, 0.25f, 2.0f}, {0, 0, -4}};
  const auto t = intersect_triangle(ray, kUnit);
  ASSERT_TRUE(t);
  EXPECT_FLOAT_EQ(*t, 0.5f);
}

TEST(Triangle, AreaAndBounds) {
  EXPECT_DOUBLE_EQ(kUnit.area(), 0.5);
  const Aabb box = kUnit.bounds();
  EXPECT_EQ(box.lo, Eigen::Vector3f(0, 0, 0));
  EXPECT_EQ(box.hi, Eigen::Vector3f(1, 1, 0));
}

}  // namespace
}  // namespace occlusion
