#include "occlusion/core/sphere_octree.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "occlusion/core/random.hpp"
#include "occlusion/core/sampling.hpp"
#include "support/brute_force.hpp"

namespace occlusion {
namespace {

using testing::brute_force_intersect;

Eigen::Vector3f random_point(Rng& rng, float lo, float hi) {
  return Eigen::Vector3f(static_cast<float>(lo + (hi - lo) * rng.uniform()),
                         static_cast<float>(lo + (hi - lo) * rng.uniform()),
                         static_cast<float>(lo + (hi - lo) * rng.uniform()));
}

// Shaped like a scan: a sparse random cloud (furniture, clutter) plus a dense
// regular grid on a floor and a wall, where neighbouring spheres overlap and
// many centroids share coordinates.
LargeVector<Sphere> scan_like_cloud() {
  Rng rng(42);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 5000; ++i) points.push_back(random_point(rng, -10.0f, 10.0f));
  const int n = 100;
  const float step = 20.0f / n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      points.emplace_back(-10.0f + i * step, -10.0f + j * step, -10.0f);  // floor z = -10
      if (i % 2 == 0 && j % 2 == 0) {
        points.emplace_back(10.0f, -10.0f + i * step, -10.0f + j * step);  // wall x = 10
      }
    }
  }
  return make_spheres(points, 0.12f);
}

std::vector<Ray> random_rays(std::size_t count, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Ray> rays;
  for (std::size_t i = 0; i < count; ++i) {
    Ray ray;
    ray.origin = random_point(rng, -12.0f, 12.0f);
    const Eigen::Vector3d d = sample_sphere_direction(rng.uniform(), rng.uniform());
    ray.direction = (d * (0.1 + 5.0 * rng.uniform())).cast<float>();
    switch (i % 4) {
      case 0:
        break;  // [0, inf)
      case 1:
        ray.t_max = static_cast<float>(10.0 * rng.uniform());
        break;
      case 2:
        ray.t_min = static_cast<float>(2.0 * rng.uniform());
        ray.t_max = ray.t_min + static_cast<float>(8.0 * rng.uniform());
        break;
      default:  // axis-aligned: exercises the zero-direction slab path
        ray.direction = Eigen::Vector3f::Zero();
        ray.direction[static_cast<int>(i / 4 % 3)] = (i / 12) % 2 ? 1.0f : -1.0f;
        break;
    }
    rays.push_back(ray);
  }
  return rays;
}

struct NamedOptions {
  const char* name;
  OctreeOptions options;
};

class SphereOctreeVersusBruteForce : public ::testing::TestWithParam<NamedOptions> {};

TEST_P(SphereOctreeVersusBruteForce, SameHitsTAndIdsOnRandomRays) {
  const LargeVector<Sphere> spheres = scan_like_cloud();
  ASSERT_GE(spheres.size(), 10000u);
  const SphereOctree tree(spheres, GetParam().options);
  const std::vector<Ray> rays = random_rays(10000, 7);
  std::size_t hit_count = 0, exits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const PrimitiveId ignore =
        i % 3 == 0 ? static_cast<PrimitiveId>(i % spheres.size()) : kNoPrimitive;
    const auto expected = brute_force_intersect(spheres, rays[i], ignore);
    const auto actual = tree.intersect(rays[i], ignore);
    ASSERT_EQ(expected.has_value(), actual.has_value()) << "ray " << i;
    EXPECT_EQ(tree.occluded(rays[i], ignore), expected.has_value()) << "ray " << i;
    if (expected) {
      ++hit_count;
      EXPECT_EQ(expected->t_hit, actual->t_hit) << "ray " << i;
      EXPECT_EQ(expected->primitive_id, actual->primitive_id) << "ray " << i;
      const Sphere& hit = spheres[expected->primitive_id];
      if ((rays[i].at(rays[i].t_min) - hit.center).norm() < hit.radius) ++exits;
    }
  }
  EXPECT_GT(hit_count, rays.size() / 5);
  EXPECT_LT(hit_count, rays.size() * 4 / 5);
  // Some rays start inside a sphere, so exit points are compared too.
  EXPECT_GT(exits, 0u);
}

// The point-cloud occlusion query: from a viewpoint to each point, ignoring
// the point itself, up to t = 1 (the point's centre).
TEST_P(SphereOctreeVersusBruteForce, RaysFromAViewpointToEveryPoint) {
  const LargeVector<Sphere> spheres = scan_like_cloud();
  const SphereOctree tree(spheres, GetParam().options);
  const Eigen::Vector3f viewpoint(1.5f, -2.0f, 0.5f);
  std::size_t blocked = 0;
  for (PrimitiveId id = 0; id < spheres.size(); id += 2) {
    const Ray ray{viewpoint, spheres[id].center - viewpoint, 0.0f, 1.0f};
    const auto expected = brute_force_intersect(spheres, ray, id);
    ASSERT_EQ(tree.occluded(ray, id), expected.has_value()) << "point " << id;
    const auto actual = tree.intersect(ray, id);
    ASSERT_EQ(actual.has_value(), expected.has_value()) << "point " << id;
    if (expected) {
      ++blocked;
      EXPECT_EQ(expected->t_hit, actual->t_hit) << "point " << id;
      EXPECT_EQ(expected->primitive_id, actual->primitive_id) << "point " << id;
    }
  }
  // Grid points seen at a grazing angle hide behind their neighbours; others don't.
  EXPECT_GT(blocked, spheres.size() / 20);
  EXPECT_LT(blocked, spheres.size() / 2);
}

OctreeOptions options_with(std::size_t leaf, float min_cell, bool accelerate) {
  OctreeOptions options;
  options.max_leaf_size = leaf;
  options.min_cell_size = min_cell;
  options.enable_acceleration = accelerate;
  return options;
}

INSTANTIATE_TEST_SUITE_P(
    Options, SphereOctreeVersusBruteForce,
    ::testing::Values(NamedOptions{"defaults", OctreeOptions{}},
                      NamedOptions{"leaf_1", options_with(1, 0.0f, true)},
                      NamedOptions{"leaf_16", options_with(16, 0.0f, true)},
                      NamedOptions{"min_cell_2", options_with(4, 2.0f, true)},
                      NamedOptions{"brute_force", options_with(4, 0.0f, false)}),
    [](const ::testing::TestParamInfo<NamedOptions>& param_info) { return param_info.param.name; });

TEST(SphereOctree, BatchEqualsSingleRayOnTwoThreads) {
  const SphereOctree tree(scan_like_cloud());
  const std::vector<Ray> rays = random_rays(20000, 11);
  std::vector<PrimitiveId> ignore(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) ignore[i] = static_cast<PrimitiveId>(i % 997);
  std::vector<std::optional<Hit>> hits(rays.size());
  std::vector<std::uint8_t> occluded(rays.size());
  tree.intersect_batch(rays.data(), rays.size(), ignore.data(), hits.data(), 2);
  tree.occluded_batch(rays.data(), rays.size(), nullptr, occluded.data(), 2);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto single = tree.intersect(rays[i], ignore[i]);
    ASSERT_EQ(single.has_value(), hits[i].has_value()) << i;
    if (single) {
      EXPECT_EQ(single->t_hit, hits[i]->t_hit);
      EXPECT_EQ(single->primitive_id, hits[i]->primitive_id);
    }
    ASSERT_EQ(tree.occluded(rays[i]), occluded[i] != 0) << i;
  }
}

TEST(SphereOctree, EqualTTiesGoToTheLowerId) {
  // Two spheres mirror-symmetric about the ray are entered at the same t.
  // Many far spheres around them make the tree split with one sphere per leaf.
  std::vector<Sphere> spheres;
  Rng rng(5);
  for (int i = 0; i < 50; ++i) spheres.push_back({random_point(rng, 20.0f, 30.0f), 0.5f});
  const PrimitiveId left = 17, right = 33;
  spheres[right] = {{0.5f, 0, 0}, 1.0f};
  spheres[left] = {{-0.5f, 0, 0}, 1.0f};
  OctreeOptions options;
  options.max_leaf_size = 1;
  const SphereOctree tree(spheres, options);
  const Ray down{{0, 0, 5}, {0, 0, -1}};
  const auto hit = tree.intersect(down);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->primitive_id, left);
  EXPECT_EQ(hit->t_hit, *intersect_sphere(down, spheres[right]));
  const auto without_left = tree.intersect(down, left);
  ASSERT_TRUE(without_left);
  EXPECT_EQ(without_left->primitive_id, right);
}

TEST(SphereOctree, RayStartingInsideAPointFindsItsExit) {
  // A row of touching spheres: from inside the first, the first's exit point
  // (t = 0.5) comes before the second's entry (t = 1.5).
  std::vector<Sphere> row;
  for (int i = 0; i < 10; ++i) row.push_back({{2.0f * static_cast<float>(i), 0, 0}, 1.0f});
  const SphereOctree tree(row);
  const auto hit = tree.intersect(Ray{{0.5f, 0, 0}, {1, 0, 0}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->primitive_id, 0u);
  EXPECT_EQ(hit->t_hit, 0.5f);
  const auto skipping_own = tree.intersect(Ray{{0.5f, 0, 0}, {1, 0, 0}}, 0);
  ASSERT_TRUE(skipping_own);
  EXPECT_EQ(skipping_own->primitive_id, 1u);
  EXPECT_EQ(skipping_own->t_hit, 0.5f);  // entry at x = 1, the spheres touch there
}

TEST(SphereOctree, StatsAndIds) {
  const LargeVector<Sphere> spheres = scan_like_cloud();
  const SphereOctree tree(spheres);
  const OctreeStats& stats = tree.stats();
  EXPECT_EQ(stats.primitives, spheres.size());
  EXPECT_LE(stats.largest_leaf, OctreeOptions{}.max_leaf_size);
  EXPECT_GT(stats.memory_bytes, spheres.size() * sizeof(Sphere));
  for (const Sphere& s : spheres) EXPECT_TRUE(tree.bounds().contains(s.center));
  EXPECT_EQ(tree.shape(4321).center, spheres[4321].center);
}

}  // namespace
}  // namespace occlusion
