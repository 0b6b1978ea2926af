// The -fscan rule's disc rays: made four at a time (a plan's matrix) they
// are the rays one surfel gets (-fscan, the live station), bit for bit, and
// the reach follows the rule on hand-worked cases.

#include "surfel_ray_rule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace occlusion {
namespace {

using surfel_ray_rule::Target;
using surfel_ray_rule::Viewpoint;

bool same_bits(const Ray& a, const Ray& b) {
  return std::memcmp(static_cast<const void*>(&a), static_cast<const void*>(&b), sizeof(Ray)) == 0;
}

// Discs, spheres and the edge cases, in a seeded jumble.
std::vector<Target> jumble(const Eigen::Vector3f& viewpoint, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coordinate(-5.0f, 5.0f), unit(-1.0f, 1.0f),
      radius(0.001f, 0.05f);
  std::vector<Target> targets;
  for (int i = 0; i < 1001; ++i) {
    Target target;
    target.surfel.center = Eigen::Vector3f(coordinate(rng), coordinate(rng), coordinate(rng));
    target.surfel.radius = radius(rng);
    target.thickness = 0.1f * radius(rng);
    switch (i % 7) {
      case 0:  // a sphere
        break;
      case 1:  // at the viewpoint
        target.surfel.center = viewpoint;
        target.surfel.normal = Eigen::Vector3f::UnitZ();
        break;
      case 2:  // within reach of the viewpoint
        target.surfel.center = viewpoint + Eigen::Vector3f(0.01f, 0.0f, 0.0f);
        target.surfel.normal = Eigen::Vector3f::UnitX();
        break;
      case 3:  // seen edge on: the thickness term is huge and clamped
        target.surfel.normal = (target.surfel.center - viewpoint).unitOrthogonal();
        break;
      default:
        target.surfel.normal = Eigen::Vector3f(unit(rng), unit(rng), unit(rng)).normalized();
    }
    targets.push_back(target);
  }
  return targets;
}

TEST(SurfelRayRule, FourAtATimeAreTheSingleRaysBitForBit) {
  for (const float fixed_reach : {-1.0f, 0.0f, 0.02f}) {
    const Viewpoint viewpoint{Eigen::Vector3f(0.3f, -1.2f, 1.5f), 0.04f, fixed_reach};
    const std::vector<Target> targets = jumble(viewpoint.position, 7);
    std::vector<Ray> rays(targets.size());
    surfel_ray_rule::rays(viewpoint, targets.data(), targets.size(), rays.data());
    std::size_t open = 0;
    for (std::size_t k = 0; k < targets.size(); ++k) {
      const Ray single = surfel_ray_rule::ray(viewpoint, targets[k]);
      ASSERT_TRUE(same_bits(single, rays[k])) << "target " << k << ", fixed reach " << fixed_reach;
      open += single.t_min <= single.t_max ? 1 : 0;
    }
    // Most rays are open intervals; the ones at or next to the viewpoint are empty.
    EXPECT_GT(open, targets.size() / 2);
    EXPECT_LT(open, targets.size());
  }
}

TEST(SurfelRayRule, ReachFollowsTheRuleOnHandWorkedCases) {
  // A disc of radius 0.02 at 4 m straight ahead, facing the viewpoint.
  Target target;
  target.surfel.center = Eigen::Vector3f(0.0f, 0.0f, 4.0f);
  target.surfel.radius = 0.02f;
  target.surfel.normal = Eigen::Vector3f(0.0f, 0.0f, -1.0f);
  const Viewpoint viewpoint{Eigen::Vector3f::Zero(), 0.1f, -1.0f};
  // Thin surface: the reach is its floor, 1.5 r = 0.03 m; t_max = 1 - 0.03 / 4.
  target.thickness = 0.001f;
  Ray ray = surfel_ray_rule::ray(viewpoint, target);
  EXPECT_FLOAT_EQ(ray.t_min, 0.1f / 4.0f);
  EXPECT_FLOAT_EQ(ray.t_max, 1.0f - 0.03f / 4.0f);
  // Noisy surface: 3 sigma = 0.036 m, between 1.5 r and 2 r.
  target.thickness = 0.012f;
  ray = surfel_ray_rule::ray(viewpoint, target);
  EXPECT_FLOAT_EQ(ray.t_max, 1.0f - 0.036f / 4.0f);
  // Seen at 60 degrees from its normal (sine 0.5): 0.072 m, capped at 2 r = 0.04.
  target.surfel.normal = Eigen::Vector3f(std::sqrt(0.75f), 0.0f, -0.5f);
  ray = surfel_ray_rule::ray(viewpoint, target);
  EXPECT_FLOAT_EQ(ray.t_max, 1.0f - 0.04f / 4.0f);
  // A sphere reaches 2 r whatever its thickness.
  target.surfel.normal = Eigen::Vector3f::Zero();
  target.thickness = 0.0f;
  ray = surfel_ray_rule::ray(viewpoint, target);
  EXPECT_FLOAT_EQ(ray.t_max, 1.0f - 0.04f / 4.0f);
  // An explicit self_tolerance replaces the rule.
  ray = surfel_ray_rule::ray({Eigen::Vector3f::Zero(), 0.1f, 0.2f}, target);
  EXPECT_FLOAT_EQ(ray.t_max, 1.0f - 0.2f / 4.0f);
  // Closer than near + reach: nothing can hide it.
  target.surfel.center = Eigen::Vector3f(0.0f, 0.0f, 0.12f);
  ray = surfel_ray_rule::ray(viewpoint, target);
  EXPECT_GT(ray.t_min, ray.t_max);
}

}  // namespace
}  // namespace occlusion
