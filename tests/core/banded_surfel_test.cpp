// Banded surfels, worked by hand: a disc in z = 0 (radius 1, band 0.01) and
// shadow rays from (0, 0, 1) whose ends (t = 1) lie below it.

#include "occlusion/core/banded_surfel.hpp"

#include <gtest/gtest.h>

#include "occlusion/core/banded_surfel_octree.hpp"

namespace occlusion {
namespace {

const Surfel kDisc{{0.0f, 0.0f, 0.0f}, 1.0f, {0.0f, 0.0f, 1.0f}};

Ray shadow_ray(const Eigen::Vector3f& end) {
  const Eigen::Vector3f origin(0.0f, 0.0f, 1.0f);
  return Ray{origin, end - origin, 0.0f, 1.0f};
}

bool hits(const BandedSurfel& disc, const Ray& ray, float* t = nullptr) {
  float t_hit = 0.0f;
  const bool hit = banded_surfel_hit(ray_components(ray), disc, true, t_hit);
  if (t) *t = t_hit;
  return hit;
}

TEST(BandedSurfel, AnEndWithinTheBandIsTheSurfacesOwn) {
  const BandedSurfel disc{kDisc, 0.01f};
  // 5 mm below the plane: within the band, not hidden; a plain surfel hides it.
  EXPECT_FALSE(hits(disc, shadow_ray({0.0f, 0.0f, -0.005f})));
  float t = 0.0f;
  EXPECT_TRUE(surfel_hit(ray_components(shadow_ray({0.0f, 0.0f, -0.005f})), kDisc, true, t));
  // 2 cm below, and 2 cm below at a slant (end (0.5, 0, -0.02)): hidden, at
  // the crossing t = 1 / 1.02.
  EXPECT_TRUE(hits(disc, shadow_ray({0.0f, 0.0f, -0.02f}), &t));
  EXPECT_NEAR(t, 1.0f / 1.02f, 1e-6f);
  EXPECT_TRUE(hits(disc, shadow_ray({0.5f, 0.0f, -0.02f})));
  // The band is measured along the normal, not along the ray: an end 5 mm
  // below the plane but far along a grazing ray is still the surface's.
  EXPECT_FALSE(hits(disc, Ray{{-10.0f, 0.0f, 0.1f}, {10.5f, 0.0f, -0.105f}, 0.0f, 1.0f}));
}

TEST(BandedSurfel, BandZeroHidesAsASurfelAndASphereIgnoresItsBand) {
  const Ray ray = shadow_ray({0.2f, 0.1f, -0.5f});
  float t = 0.0f;
  EXPECT_EQ(hits(BandedSurfel{kDisc, 0.0f}, ray), surfel_hit(ray_components(ray), kDisc, true, t));
  // A sphere of radius 0.1 at the origin, band 1: a ray through it hides its end.
  const Surfel sphere{{0.0f, 0.0f, 0.0f}, 0.1f, {0.0f, 0.0f, 0.0f}};
  EXPECT_TRUE(hits(BandedSurfel{sphere, 1.0f}, shadow_ray({0.0f, 0.0f, -0.05f - 0.1f})));
}

TEST(BandedSurfel, TheOctreeAnswersAsTheKernel) {
  // A wall of discs in x = 0 and points behind it at 5 mm and at 5 cm.
  LargeVector<BandedSurfel> wall;
  for (int y = -5; y <= 5; ++y) {
    for (int z = -5; z <= 5; ++z) {
      wall.push_back({{{0.0f, 0.1f * y, 0.1f * z}, 0.08f, {1.0f, 0.0f, 0.0f}}, 0.01f});
    }
  }
  const BandedSurfelOctree tree(wall);
  const Eigen::Vector3f viewpoint(-2.0f, 0.05f, 0.0f);
  for (const float behind : {0.005f, 0.05f}) {
    const Eigen::Vector3f end(behind, 0.12f, 0.13f);
    const Ray ray{viewpoint, end - viewpoint, 0.0f, 1.0f};
    EXPECT_EQ(tree.occluded(ray), behind > 0.01f) << behind;
  }
}

}  // namespace
}  // namespace occlusion
