#include "occlusion/core/triangle_octree.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

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

// A soup of small random triangles plus a finely gridded floor and wall: random
// sizes and orientations, and many shared edges on the axis-aligned planes.
std::vector<Triangle> test_scene(std::size_t soup_count) {
  Rng rng(42);
  std::vector<Triangle> triangles;
  for (std::size_t i = 0; i < soup_count; ++i) {
    const Eigen::Vector3f centre = random_point(rng, -10.0f, 10.0f);
    const float size = static_cast<float>(0.05 + 1.5 * rng.uniform() * rng.uniform());
    triangles.push_back({centre + size * random_point(rng, -1, 1),
                         centre + size * random_point(rng, -1, 1),
                         centre + size * random_point(rng, -1, 1)});
  }
  const int n = 40;
  const float step = 20.0f / n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const float x = -10.0f + i * step, y = -10.0f + j * step;
      // floor z = -10 and wall x = 10
      triangles.push_back({{x, y, -10}, {x + step, y, -10}, {x + step, y + step, -10}});
      triangles.push_back({{x, y, -10}, {x + step, y + step, -10}, {x, y + step, -10}});
      triangles.push_back({{10, x, y}, {10, x + step, y}, {10, x + step, y + step}});
      triangles.push_back({{10, x, y}, {10, x + step, y + step}, {10, x, y + step}});
    }
  }
  return triangles;
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

class OctreeVersusBruteForce : public ::testing::TestWithParam<NamedOptions> {};

TEST_P(OctreeVersusBruteForce, SameHitsAndTOnRandomRays) {
  const std::vector<PackedTriangle> packed = pack_triangles(test_scene(10000));
  ASSERT_GE(packed.size(), 10000u);
  const TriangleOctree tree(packed, GetParam().options);
  const std::vector<Ray> rays = random_rays(10000, 7);
  std::size_t hit_count = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    // Every third ray ignores a random primitive (a sample's own triangle).
    const PrimitiveId ignore =
        i % 3 == 0 ? static_cast<PrimitiveId>(i % packed.size()) : kNoPrimitive;
    const auto expected = brute_force_intersect(packed, rays[i], ignore);
    const auto actual = tree.intersect(rays[i], ignore);
    ASSERT_EQ(expected.has_value(), actual.has_value()) << "ray " << i;
    EXPECT_EQ(tree.occluded(rays[i], ignore), expected.has_value()) << "ray " << i;
    if (expected) {
      ++hit_count;
      EXPECT_EQ(expected->t_hit, actual->t_hit) << "ray " << i;
      EXPECT_EQ(expected->primitive_id, actual->primitive_id) << "ray " << i;
    }
  }
  // Both outcomes must be well represented for the comparison to mean anything.
  EXPECT_GT(hit_count, rays.size() / 5);
  EXPECT_LT(hit_count, rays.size() * 4 / 5);
}

TEST_P(OctreeVersusBruteForce, ShadowRaysFromSurfaceSamples) {
  const std::vector<Triangle> triangles = test_scene(10000);
  const std::vector<PackedTriangle> packed = pack_triangles(triangles);
  const TriangleOctree tree(packed, GetParam().options);
  Rng rng(99);
  std::size_t blocked = 0;
  const std::size_t count = 10000;
  for (std::size_t i = 0; i < count; ++i) {
    const auto id = static_cast<PrimitiveId>(rng.next() % triangles.size());
    const Triangle& tri = triangles[id];
    const Eigen::Vector3f sample =
        sample_triangle(tri.v0.cast<double>(), tri.v1.cast<double>(), tri.v2.cast<double>(),
                        rng.uniform(), rng.uniform())
            .cast<float>();
    Ray ray{sample, random_point(rng, -9, 9) - sample, 1e-4f, 1.0f - 1e-4f};
    const bool expected = brute_force_intersect(packed, ray, id).has_value();
    ASSERT_EQ(tree.occluded(ray, id), expected) << "ray " << i;
    blocked += expected ? 1 : 0;
  }
  EXPECT_GT(blocked, count / 20);
  EXPECT_LT(blocked, count * 19 / 20);
}

OctreeOptions options_with(std::size_t leaf, float min_cell, bool accelerate) {
  OctreeOptions options;
  options.max_leaf_size = leaf;
  options.min_cell_size = min_cell;
  options.enable_acceleration = accelerate;
  return options;
}

INSTANTIATE_TEST_SUITE_P(
    Options, OctreeVersusBruteForce,
    ::testing::Values(NamedOptions{"defaults", OctreeOptions{}},
                      NamedOptions{"leaf_1", options_with(1, 0.0f, true)},
                      NamedOptions{"leaf_16", options_with(16, 0.0f, true)},
                      NamedOptions{"min_cell_2", options_with(4, 2.0f, true)},
                      NamedOptions{"brute_force", options_with(4, 0.0f, false)}),
    [](const ::testing::TestParamInfo<NamedOptions>& param_info) { return param_info.param.name; });

TEST(Octree, BatchEqualsSingleRayOnAllThreads) {
  const TriangleOctree tree(pack_triangles(test_scene(10000)));
  const std::vector<Ray> rays = random_rays(20000, 11);
  std::vector<PrimitiveId> ignore(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) ignore[i] = static_cast<PrimitiveId>(i % 997);
  std::vector<std::optional<Hit>> hits(rays.size());
  std::vector<std::uint8_t> occluded(rays.size());
  for (const unsigned threads : {1u, 2u, 0u}) {
    tree.intersect_batch(rays.data(), rays.size(), ignore.data(), hits.data(), threads);
    tree.occluded_batch(rays.data(), rays.size(), nullptr, occluded.data(), threads);
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
}

// The mesh path of compute_mesh_occlusion: faces packed straight from the mesh
// around an origin into a LargeVector (huge pages for big ones), and the tree
// built from it, equal the std::vector path bit for bit.
TEST(Octree, BuiltFromAPackedMeshEqualsTheVectorPath) {
  // 56,400 triangles, over 2 MiB packed: the LargeVector takes huge pages.
  const std::vector<Triangle> scene = test_scene(50000);
  TriangleMesh mesh;
  const Eigen::Vector3d origin(0.25, -1.5, 3.0);
  for (const Triangle& t : scene) {
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const Eigen::Vector3f& v : {t.v0, t.v1, t.v2}) mesh.vertices.push_back(v.cast<double>());
    mesh.faces.push_back({first, first + 1, first + 2});
  }
  std::vector<Triangle> local;
  for (const auto& face : mesh.faces) {
    local.push_back({(mesh.vertices[face[0]] - origin).cast<float>(),
                     (mesh.vertices[face[1]] - origin).cast<float>(),
                     (mesh.vertices[face[2]] - origin).cast<float>()});
  }
  const LargeVector<PackedTriangle> packed = pack_triangles(mesh, origin);
  const std::vector<PackedTriangle> expected = pack_triangles(local);
  ASSERT_EQ(packed.size(), expected.size());
  for (std::size_t i = 0; i < packed.size(); ++i) {
    ASSERT_EQ(packed[i].v0, expected[i].v0) << i;
    ASSERT_EQ(packed[i].e1, expected[i].e1) << i;
    ASSERT_EQ(packed[i].e2, expected[i].e2) << i;
    ASSERT_EQ(packed[i].normal, expected[i].normal) << i;
  }
  const TriangleOctree from_buffer(packed);
  const TriangleOctree from_vector(expected);
  EXPECT_EQ(from_buffer.stats().inner_nodes, from_vector.stats().inner_nodes);
  EXPECT_EQ(from_buffer.stats().leaves, from_vector.stats().leaves);
  const std::vector<Ray> rays = random_rays(20000, 5);
  std::vector<std::optional<Hit>> a(rays.size()), b(rays.size());
  from_buffer.intersect_batch(rays.data(), rays.size(), nullptr, a.data(), 2);
  from_vector.intersect_batch(rays.data(), rays.size(), nullptr, b.data(), 2);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_EQ(a[i].has_value(), b[i].has_value()) << i;
    if (a[i]) {
      EXPECT_EQ(a[i]->t_hit, b[i]->t_hit) << i;
      EXPECT_EQ(a[i]->primitive_id, b[i]->primitive_id) << i;
    }
  }
}

// Shapes handed over (a LargeVector moved in) are put in leaf order in place,
// block by block, rather than gathered into a second array: every id must
// still map back to its shape, and the tree must be the gathered one, for
// counts that fill whole blocks of 1,024, leave a last block part full, or
// make one shape.
TEST(Octree, ShapesHandedOverAreReorderedInPlaceAsTheGatheredCopy) {
  const std::vector<Triangle> scene = test_scene(50000);
  for (const std::size_t count :
       {std::size_t{1}, std::size_t{1023}, std::size_t{1024}, std::size_t{4096}, scene.size()}) {
    LargeVector<PackedTriangle> packed;
    for (std::size_t i = 0; i < count; ++i) packed.emplace_back(scene[i]);
    const TriangleOctree gathered(packed);
    LargeVector<PackedTriangle> handed = packed;
    const TriangleOctree in_place(std::move(handed));
    EXPECT_TRUE(handed.empty());
    ASSERT_EQ(in_place.size(), count);
    EXPECT_EQ(in_place.stats().inner_nodes, gathered.stats().inner_nodes);
    EXPECT_EQ(in_place.stats().leaves, gathered.stats().leaves);
    EXPECT_EQ(in_place.stats().depth, gathered.stats().depth);
    for (std::size_t i = 0; i < count; ++i) {
      const auto id = static_cast<PrimitiveId>(i);
      ASSERT_EQ(in_place.shape(id).v0, packed[i].v0) << count << " shapes, id " << i;
      ASSERT_EQ(in_place.shape(id).e1, packed[i].e1) << count << " shapes, id " << i;
      ASSERT_EQ(in_place.shape(id).e2, packed[i].e2) << count << " shapes, id " << i;
    }
    const std::vector<Ray> rays = random_rays(2000, 7);
    std::vector<std::optional<Hit>> a(rays.size()), b(rays.size());
    in_place.intersect_batch(rays.data(), rays.size(), nullptr, a.data(), 2);
    gathered.intersect_batch(rays.data(), rays.size(), nullptr, b.data(), 2);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      ASSERT_EQ(a[i].has_value(), b[i].has_value()) << i;
      if (a[i]) {
        EXPECT_EQ(a[i]->t_hit, b[i]->t_hit) << i;
        EXPECT_EQ(a[i]->primitive_id, b[i]->primitive_id) << i;
      }
      if (count <= 4096) {
        const auto brute = brute_force_intersect(packed, rays[i]);
        ASSERT_EQ(a[i].has_value(), brute.has_value()) << i;
        if (a[i]) {
          EXPECT_EQ(a[i]->t_hit, brute->t_hit) << i;
        }
      }
    }
  }
}

TEST(Octree, SubdividesAndBoundsEverything) {
  const std::vector<Triangle> triangles = test_scene(10000);
  const TriangleOctree tree(pack_triangles(triangles));
  const OctreeStats& stats = tree.stats();
  EXPECT_EQ(stats.primitives, triangles.size());
  EXPECT_GT(stats.inner_nodes, 100u);
  EXPECT_LE(stats.largest_leaf, OctreeOptions{}.max_leaf_size);
  for (const Triangle& tri : triangles) {
    EXPECT_TRUE(tree.bounds().contains(tri.v0) && tree.bounds().contains(tri.v1) &&
                tree.bounds().contains(tri.v2));
  }
  // Ids map back to the construction order.
  EXPECT_EQ(tree.shape(123).v0, PackedTriangle(triangles[123]).v0);
}

TEST(Octree, BruteForceModeIsOneLeaf) {
  OctreeOptions options;
  options.enable_acceleration = false;
  const TriangleOctree tree(pack_triangles(test_scene(500)), options);
  EXPECT_EQ(tree.stats().leaves, 1u);
  EXPECT_EQ(tree.stats().largest_leaf, tree.size());
}

TEST(Octree, CoincidentCentroidsTerminate) {
  // 100 copies of one triangle: no split can separate them.
  const std::vector<Triangle> copies(100, Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const TriangleOctree tree(pack_triangles(copies));
  EXPECT_EQ(tree.stats().leaves, 1u);
  const auto hit = tree.intersect(Ray{{0.2f, 0.2f, 1}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->primitive_id, 0u);  // all tie at t = 1: the lowest id wins
}

TEST(Octree, EmptySceneNeverHits) {
  const TriangleOctree tree(std::vector<PackedTriangle>{});
  EXPECT_FALSE(tree.intersect(Ray{}));
  EXPECT_FALSE(tree.occluded(Ray{}));
  EXPECT_EQ(tree.size(), 0u);
}

TEST(Octree, RayThroughASharedEdgeOrVertexHits) {
  // The unit square as two triangles sharing the diagonal (0,0)-(1,1), plus a
  // far-away triangle so the tree is not a single leaf.
  const std::vector<Triangle> square = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}},
                                        {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                        {{5, 5, 5}, {6, 5, 5}, {5, 6, 5}}};
  OctreeOptions options;
  options.max_leaf_size = 1;
  const TriangleOctree tree(pack_triangles(square), options);
  for (const Eigen::Vector3f& through :
       {Eigen::Vector3f(0.5f, 0.5f, 0), Eigen::Vector3f(0.25f, 0.25f, 0), Eigen::Vector3f(1, 1, 0),
        Eigen::Vector3f(0, 0, 0)}) {
    const Ray ray{through + Eigen::Vector3f(0, 0, 2), {0, 0, -1}};
    const auto hit = tree.intersect(ray);
    ASSERT_TRUE(hit) << through.transpose();
    EXPECT_FLOAT_EQ(hit->t_hit, 2.0f);
    EXPECT_EQ(hit->primitive_id, 0u);  // both triangles tie: the lower id
    // Ignoring one of the two still hits the other: the edge is in both.
    EXPECT_TRUE(tree.occluded(ray, 0));
    EXPECT_TRUE(tree.occluded(ray, 1));
  }
}

TEST(Octree, ShadowRayFromASharedEdgeIsNotBlockedByTheNeighbour) {
  // A sample exactly on the edge shared by two faces: its own face is ignored and
  // the neighbour touches the ray only at t = 0, below t_min.
  const std::vector<Triangle> square = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}},
                                        {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  const TriangleOctree tree(pack_triangles(square));
  const Ray shadow{{0.5f, 0.5f, 0}, {0.3f, -0.2f, 2}, 1e-5f, 1.0f - 1e-5f};
  EXPECT_FALSE(tree.occluded(shadow, 0));
  EXPECT_FALSE(tree.occluded(shadow, 1));
}

TEST(Octree, HitAtExactlyTMaxCounts) {
  const std::vector<Triangle> one = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const TriangleOctree tree(pack_triangles(one));
  Ray ray{{0.25f, 0.25f, 1}, {0, 0, -1}, 0.0f, 1.0f};
  EXPECT_TRUE(tree.occluded(ray));
  ray.t_max = std::nextafter(1.0f, 0.0f);
  EXPECT_FALSE(tree.occluded(ray));
  ray.t_min = 2.0f;
  ray.t_max = 1.0f;  // an empty interval
  EXPECT_FALSE(tree.intersect(ray));
}

TEST(Octree, RejectsBadOptions) {
  OctreeOptions options;
  options.max_leaf_size = 0;
  EXPECT_THROW(TriangleOctree(std::vector<PackedTriangle>{}, options), std::invalid_argument);
  options = OctreeOptions{};
  options.max_depth = 99;
  EXPECT_THROW(TriangleOctree(std::vector<PackedTriangle>{}, options), std::invalid_argument);
  options = OctreeOptions{};
  options.min_cell_size = -1.0f;
  EXPECT_THROW(TriangleOctree(std::vector<PackedTriangle>{}, options), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
