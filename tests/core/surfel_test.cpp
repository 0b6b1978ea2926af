#include "occlusion/core/surfel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace occlusion {
namespace {

// A disc of radius 1 lying in the plane z = 5, centred on the z axis.
const Surfel kFloorDisc{{0, 0, 5}, 1.0f, {0, 0, 1}};

TEST(Surfel, RayThroughThePlaneHitsAtTheCrossing) {
  const auto t = intersect_surfel(Ray{{0.5f, 0.25f, 0}, {0, 0, 2}}, kFloorDisc);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 2.5f);
  // Two-sided: from above, too.
  const auto down = intersect_surfel(Ray{{0, 0, 8}, {0, 0, -1}}, kFloorDisc);
  ASSERT_TRUE(down);
  EXPECT_EQ(*down, 3.0f);
}

TEST(Surfel, SlantedRayHitsWhereItCrossesInsideTheRim) {
  // From (-3, 0, 1) along (1, 0, 1): crosses z = 5 at x = 1 (the rim) at t = 4.
  const auto rim = intersect_surfel(Ray{{-3, 0, 1}, {1, 0, 1}}, kFloorDisc);
  ASSERT_TRUE(rim);
  EXPECT_FLOAT_EQ(*rim, 4.0f);
  // Crossing at x = 1.01: outside the rim.
  EXPECT_FALSE(intersect_surfel(Ray{{-2.99f, 0, 1}, {1, 0, 1}}, kFloorDisc));
}

TEST(Surfel, RayInThePlaneOrParallelToItMisses) {
  EXPECT_FALSE(intersect_surfel(Ray{{-3, 0, 5}, {1, 0, 0}}, kFloorDisc));
  EXPECT_FALSE(intersect_surfel(Ray{{-3, 0, 4.9f}, {1, 0, 0}}, kFloorDisc));
}

TEST(Surfel, IntervalIsClosedAndRespected) {
  const Ray up{{0, 0, 0}, {0, 0, 1}, 0.0f, 5.0f};
  ASSERT_TRUE(intersect_surfel(up, kFloorDisc));  // t = 5 = t_max hits
  EXPECT_FALSE(intersect_surfel(Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 4.999f}, kFloorDisc));
  EXPECT_FALSE(intersect_surfel(Ray{{0, 0, 0}, {0, 0, 1}, 5.001f, 9.0f}, kFloorDisc));
  EXPECT_FALSE(intersect_surfel(Ray{{0, 0, 6}, {0, 0, 1}}, kFloorDisc));  // behind the origin
}

TEST(Surfel, UnorientedSurfelIsTheSphereOfItsRadius) {
  const Surfel ball{{0, 0, 5}, 1.0f, {0, 0, 0}};
  const Sphere sphere{{0, 0, 5}, 1.0f};
  for (const Ray& ray : {Ray{{0, 0, 0}, {0, 0, 1}}, Ray{{0.6f, 0, 0}, {0, 0, 1}},
                         Ray{{0, 0, 5}, {1, 0, 0}}, Ray{{2, 0, 0}, {0, 0, 1}}}) {
    const auto surfel_t = intersect_surfel(ray, ball);
    const auto sphere_t = intersect_sphere(ray, sphere);
    ASSERT_EQ(surfel_t.has_value(), sphere_t.has_value());
    if (surfel_t) {
      EXPECT_EQ(*surfel_t, *sphere_t);
    }
  }
}

TEST(Surfel, ZeroOrNanRadiusIsNeverHit) {
  EXPECT_FALSE(intersect_surfel(Ray{{0, 0, 0}, {0, 0, 1}}, Surfel{{0, 0, 5}, 0.0f, {0, 0, 1}}));
  EXPECT_FALSE(
      intersect_surfel(Ray{{0, 0, 0}, {0, 0, 1}}, Surfel{{0, 0, 5}, std::nanf(""), {0, 0, 1}}));
}

TEST(Surfel, SmallDiscFarAwayIsHitPrecisely) {
  // A 1 mm disc 1 km out: the crossing is measured from the disc's centre.
  const Surfel far{{1000, 0, 0}, 0.001f, {1, 0, 0}};
  EXPECT_TRUE(intersect_surfel(Ray{{0, 0.0009f, 0}, {1, 0, 0}}, far));
  EXPECT_FALSE(intersect_surfel(Ray{{0, 0.0011f, 0}, {1, 0, 0}}, far));
}

TEST(Surfel, BoundsAreTheDiscsBox) {
  const Surfel tilted{{1, 2, 3}, 2.0f, Eigen::Vector3f(1, 0, 1).normalized()};
  const Aabb box = tilted.bounds();
  // Along y the disc reaches its full radius; along x and z r sqrt(1/2).
  EXPECT_NEAR(box.hi.y() - 2.0f, 2.0f, 1e-3f);
  EXPECT_NEAR(box.hi.x() - 1.0f, 2.0f * std::sqrt(0.5f), 1e-3f);
  EXPECT_NEAR(3.0f - box.lo.z(), 2.0f * std::sqrt(0.5f), 1e-3f);
  // A floor disc is flat (but for the rounding margin).
  EXPECT_LT(kFloorDisc.bounds().extent().z(), 1e-3f);
}

TEST(Surfel, MakeSurfelsNormalisesAndChecks) {
  const auto surfels = make_surfels({{0, 0, 0}, {1, 1, 1}}, {{0, 0, 3}, {0, 0, 0}}, {0.5f, 0.25f});
  ASSERT_EQ(surfels.size(), 2u);
  EXPECT_EQ(surfels[0].normal, Eigen::Vector3f(0, 0, 1));
  EXPECT_FALSE(surfels[1].oriented());
  EXPECT_THROW(make_surfels({{0, 0, 0}}, {{0, 0, 1}}, {0.0f}), std::invalid_argument);
  EXPECT_THROW(make_surfels({{0, 0, 0}}, {{0, 0, 1}}, {}), std::invalid_argument);
  EXPECT_THROW(make_surfels({{0, 0, 0}}, {{std::nanf(""), 0, 1}}, {1.0f}), std::invalid_argument);
  EXPECT_THROW(make_surfels({{0, 0, 0}}, {{0, 0, 1}}, {std::numeric_limits<float>::infinity()}),
               std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
