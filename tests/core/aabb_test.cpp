#include "occlusion/core/aabb.hpp"

#include <gtest/gtest.h>

namespace occlusion {
namespace {

Aabb unit_box() {
  Aabb box;
  box.extend(Eigen::Vector3f(0, 0, 0));
  box.extend(Eigen::Vector3f(1, 1, 1));
  return box;
}

bool hits(const Ray& ray, float* enter = nullptr, float* exit = nullptr) {
  float t0 = 0, t1 = 0;
  const bool hit = intersect_aabb(ray, safe_inverse(ray.direction), unit_box(), t0, t1);
  if (enter) *enter = t0;
  if (exit) *exit = t1;
  return hit;
}

TEST(Aabb, EmptyUntilExtended) {
  Aabb box;
  EXPECT_TRUE(box.empty());
  box.extend(Eigen::Vector3f(1, 2, 3));
  EXPECT_FALSE(box.empty());
  EXPECT_TRUE(box.contains(Eigen::Vector3f(1, 2, 3)));
}

TEST(Aabb, ThroughTheMiddleGivesEntryAndExit) {
  float enter = 0, exit = 0;
  ASSERT_TRUE(hits(Ray{{-1, 0.5f, 0.5f}, {1, 0, 0}}, &enter, &exit));
  EXPECT_FLOAT_EQ(enter, 1.0f);
  EXPECT_FLOAT_EQ(exit, 2.0f);
}

TEST(Aabb, OriginInsideStartsAtTMin) {
  float enter = 0, exit = 0;
  ASSERT_TRUE(hits(Ray{{0.5f, 0.5f, 0.5f}, {0, 0, 1}}, &enter, &exit));
  EXPECT_FLOAT_EQ(enter, 0.0f);
  EXPECT_FLOAT_EQ(exit, 0.5f);
}

TEST(Aabb, TouchingAFaceEdgeOrCornerHits) {
  EXPECT_TRUE(hits(Ray{{-1, 1.0f, 0.5f}, {1, 0, 0}}));  // slides along the face y = 1
  EXPECT_TRUE(hits(Ray{{-1, 1.0f, 1.0f}, {1, 0, 0}}));  // along an edge
  EXPECT_TRUE(hits(Ray{{-1, -1, -1}, {1, 1, 1}}));      // through corners
  EXPECT_TRUE(hits(Ray{{2, 0, 1}, {-1, 1, 0}}));        // touches the edge x=1,y=1 at one point
}

TEST(Aabb, ParallelOutsideMisses) {
  EXPECT_FALSE(hits(Ray{{-1, 1.5f, 0.5f}, {1, 0, 0}}));
  EXPECT_FALSE(hits(Ray{{0.5f, 0.5f, 2.0f}, {1, 0, 0}}));
}

TEST(Aabb, RespectsTheInterval) {
  Ray ray{{-1, 0.5f, 0.5f}, {1, 0, 0}};
  ray.t_max = 0.99f;
  EXPECT_FALSE(hits(ray));
  ray.t_max = 1.0f;  // closed: touching at t_max hits
  EXPECT_TRUE(hits(ray));
  ray.t_min = 2.5f;
  ray.t_max = 10.0f;
  EXPECT_FALSE(hits(ray));
}

TEST(Aabb, BehindMisses) {
  EXPECT_FALSE(hits(Ray{{-1, 0.5f, 0.5f}, {-1, 0, 0}}));
}

TEST(Aabb, SafeInverseKeepsTheSignOfZero) {
  const Eigen::Vector3f inv = safe_inverse(Eigen::Vector3f(0.0f, -0.0f, 2.0f));
  EXPECT_GT(inv.x(), 1e29f);
  EXPECT_LT(inv.y(), -1e29f);
  EXPECT_FLOAT_EQ(inv.z(), 0.5f);
}

}  // namespace
}  // namespace occlusion
