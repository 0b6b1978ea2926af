#include "occlusion/core/sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace occlusion {
namespace {

// Unit sphere on the z axis, five units up: a ray up the axis from the origin
// enters at t = 4 and leaves at t = 6.
const Sphere kAhead{{0, 0, 5}, 1.0f};
const Ray kUp{{0, 0, 0}, {0, 0, 1}};

TEST(Sphere, ThroughTheCentreHitsTheEntryPoint) {
  const auto t = intersect_sphere(kUp, kAhead);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 4.0f);
}

TEST(Sphere, OffCentreHitAtKnownT) {
  // Crossing at distance 0.6 from the centre: half-chord 0.8.
  const Ray ray{{0.6f, 0, 0}, {0, 0, 1}};
  const auto t = intersect_sphere(ray, kAhead);
  ASSERT_TRUE(t);
  EXPECT_FLOAT_EQ(*t, 4.2f);
}

TEST(Sphere, TangentRayHitsAndOneUlpFurtherMisses) {
  const Sphere unit{{0, 0, 0}, 1.0f};
  const auto t = intersect_sphere(Ray{{-5, 1, 0}, {1, 0, 0}}, unit);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 5.0f);
  EXPECT_FALSE(intersect_sphere(Ray{{-5, std::nextafter(1.0f, 2.0f), 0}, {1, 0, 0}}, unit));
}

TEST(Sphere, Misses) {
  EXPECT_FALSE(intersect_sphere(Ray{{1.5f, 0, 0}, {0, 0, 1}}, kAhead));
  EXPECT_FALSE(intersect_sphere(Ray{{0, 0, 0}, {1, 0, 0}}, kAhead));
}

TEST(Sphere, OriginInsideHitsTheExitPoint) {
  const auto from_centre = intersect_sphere(Ray{{0, 0, 5}, {0, 0, 1}}, kAhead);
  ASSERT_TRUE(from_centre);
  EXPECT_EQ(*from_centre, 1.0f);
  const auto off_centre = intersect_sphere(Ray{{0, 0, 4.5f}, {0, 0, -1}}, kAhead);
  ASSERT_TRUE(off_centre);
  EXPECT_EQ(*off_centre, 0.5f);
}

TEST(Sphere, SphereBehindTheOriginMisses) {
  EXPECT_FALSE(intersect_sphere(Ray{{0, 0, 0}, {0, 0, -1}}, kAhead));
  // Starting just past the far side, going on.
  EXPECT_FALSE(intersect_sphere(Ray{{0, 0, 6.5f}, {0, 0, 1}}, kAhead));
}

TEST(Sphere, IntervalIsClosedAtBothEnds) {
  Ray ray = kUp;  // roots at 4 and 6
  ray.t_max = 4.0f;
  EXPECT_EQ(intersect_sphere(ray, kAhead), 4.0f);
  ray.t_max = std::nextafter(4.0f, 0.0f);
  EXPECT_FALSE(intersect_sphere(ray, kAhead));

  ray.t_max = 10.0f;
  ray.t_min = 4.0f;
  EXPECT_EQ(intersect_sphere(ray, kAhead), 4.0f);
  // The entry lies before t_min: the smallest root in the interval is the exit.
  ray.t_min = std::nextafter(4.0f, 5.0f);
  EXPECT_EQ(intersect_sphere(ray, kAhead), 6.0f);
  ray.t_min = 6.0f;
  EXPECT_EQ(intersect_sphere(ray, kAhead), 6.0f);
  ray.t_min = std::nextafter(6.0f, 7.0f);
  EXPECT_FALSE(intersect_sphere(ray, kAhead));

  // An interval strictly between the roots holds no root.
  ray.t_min = 4.5f;
  ray.t_max = 5.5f;
  EXPECT_FALSE(intersect_sphere(ray, kAhead));
}

TEST(Sphere, RadiusZeroIsNeverHit) {
  const Sphere point{{0, 0, 5}, 0.0f};
  EXPECT_FALSE(intersect_sphere(kUp, point));
  EXPECT_FALSE(intersect_sphere(Ray{{0, 0, 5}, {0, 0, 1}}, point));  // from the point itself
}

TEST(Sphere, UnnormalisedDirectionScalesT) {
  // t is in units of the direction: four units per step reaches z = 4 at t = 1.
  const auto t = intersect_sphere(Ray{{0, 0, 0}, {0, 0, 4}}, kAhead);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 1.0f);
  // A shadow-ray style direction (target - origin), tilted: t = 1 at the target,
  // which lies inside the sphere, so the entry comes before t = 1.
  const Eigen::Vector3f origin(3, -2, 1);
  const Ray shadow{origin, Eigen::Vector3f(0.3f, 0, 4.5f) - origin, 0.0f, 1.0f};
  const auto hit = intersect_sphere(shadow, kAhead);
  ASSERT_TRUE(hit);
  EXPECT_LE(*hit, 1.0f);
  EXPECT_NEAR((shadow.at(*hit) - kAhead.center).norm(), kAhead.radius, 1e-5f);
}

TEST(Sphere, ZeroDirectionNeverHits) {
  EXPECT_FALSE(intersect_sphere(Ray{{0, 0, 5}, {0, 0, 0}}, kAhead));
}

TEST(Sphere, SmallFarSphereIsHitAccurately) {
  // The textbook b^2 - 4ac loses every significant digit here in float:
  // b^2 ~ 4e8 and the discriminant ~ 4e-6.
  const Sphere far{{0, 0, 1e4f}, 1e-3f};
  const auto t = intersect_sphere(Ray{{6e-4f, 0, 0}, {0, 0, 1}}, far);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 1e4f - 8e-4f, 1e-3f);  // half-chord 8e-4; float spacing at 1e4 ~ 1e-3
  EXPECT_FALSE(intersect_sphere(Ray{{1.1e-3f, 0, 0}, {0, 0, 1}}, far));
  // And sideways, where the offset from the closest point is what counts.
  const auto across = intersect_sphere(Ray{{-1e4f, 9e-4f, 1e4f}, {1, 0, 0}}, far);
  ASSERT_TRUE(across);
  EXPECT_NEAR(*across, 1e4f - std::sqrt(1e-6f - 8.1e-7f), 1e-3f);
}

TEST(Sphere, BoundsAreTheCubeAroundIt) {
  const Sphere s{{1, -2, 3}, 0.5f};
  const Aabb box = s.bounds();
  EXPECT_EQ(box.lo, Eigen::Vector3f(0.5f, -2.5f, 2.5f));
  EXPECT_EQ(box.hi, Eigen::Vector3f(1.5f, -1.5f, 3.5f));
  EXPECT_EQ(s.centroid(), s.center);
}

TEST(Sphere, MakeSpheresKeepsOrderAndRadius) {
  const std::vector<Eigen::Vector3f> centres = {{0, 0, 0}, {1, 2, 3}, {-4, 5, -6}};
  const LargeVector<Sphere> spheres = make_spheres(centres, 0.25f);
  ASSERT_EQ(spheres.size(), centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i) {
    EXPECT_EQ(spheres[i].center, centres[i]);
    EXPECT_EQ(spheres[i].radius, 0.25f);
  }
  EXPECT_TRUE(make_spheres({}, 1.0f).empty());
}

TEST(Sphere, MakeSpheresRejectsBadInput) {
  const std::vector<Eigen::Vector3f> centres = {{0, 0, 0}};
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const float radius : {0.0f, -1.0f, inf, nan}) {
    EXPECT_THROW(make_spheres(centres, radius), std::invalid_argument) << radius;
  }
  EXPECT_THROW(make_spheres({{0, 0, 0}, {nan, 0, 0}}, 1.0f), std::invalid_argument);
  EXPECT_THROW(make_spheres({{0, inf, 0}}, 1.0f), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
