// The packet traversals (SSE2, AVX2) against the single-ray traversal and
// brute force, ray by ray, on rays shaped like the analyses' (shadow rays to a
// few viewpoints, rays out of viewpoints) and on the edge cases: rays lying in
// a face plane, zero-length directions, empty and NaN intervals, hits exactly
// at t_max, ties between coincident primitives, batches not a multiple of the
// packet width.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "occlusion/core/random.hpp"
#include "occlusion/core/sampling.hpp"
#include "occlusion/core/sphere_octree.hpp"
#include "occlusion/core/surfel_octree.hpp"
#include "occlusion/core/triangle_octree.hpp"
#include "support/brute_force.hpp"

namespace occlusion {
namespace {

using testing::brute_force_intersect;

// Drawn z, y, x in sequence: the order gcc gave the three draws when they
// were arguments of one call (unspecified in C++; clang drew x first and built
// another scene), so every compiler builds the scenes these tests were sized on.
Eigen::Vector3f random_point(Rng& rng, float lo, float hi) {
  const auto z = static_cast<float>(lo + (hi - lo) * rng.uniform());
  const auto y = static_cast<float>(lo + (hi - lo) * rng.uniform());
  const auto x = static_cast<float>(lo + (hi - lo) * rng.uniform());
  return Eigen::Vector3f(x, y, z);
}

// A room-like scene: random clutter, a gridded floor (z = 0) and wall (x = 10)
// with shared edges, and every tenth clutter triangle duplicated (a tie: same
// t, the lower id must win).
std::vector<PackedTriangle> room_triangles() {
  Rng rng(5);
  std::vector<Triangle> triangles;
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3f centre = random_point(rng, 0.5f, 9.5f);
    const float size = static_cast<float>(0.1 + 0.8 * rng.uniform());
    triangles.push_back({centre + size * random_point(rng, -1, 1),
                         centre + size * random_point(rng, -1, 1),
                         centre + size * random_point(rng, -1, 1)});
    if (i % 10 == 0) triangles.push_back(triangles.back());
  }
  const int n = 20;
  const float step = 10.0f / n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const float a = i * step, b = j * step;
      triangles.push_back({{a, b, 0}, {a + step, b, 0}, {a + step, b + step, 0}});
      triangles.push_back({{a, b, 0}, {a + step, b + step, 0}, {a, b + step, 0}});
      triangles.push_back({{10, a, b}, {10, a + step, b}, {10, a + step, b + step}});
      triangles.push_back({{10, a, b}, {10, a + step, b + step}, {10, a, b + step}});
    }
  }
  return pack_triangles(triangles);
}

LargeVector<Sphere> room_spheres() {
  Rng rng(6);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 4000; ++i) points.push_back(random_point(rng, 0.0f, 10.0f));
  for (int i = 0; i < 80; ++i) {
    for (int j = 0; j < 80; ++j) points.emplace_back(i * 0.125f, j * 0.125f, 0.0f);
  }
  points.push_back(points[17]);  // coincident points: a tie
  return make_spheres(points, 0.08f);
}

// Discs in every orientation among the clutter, the gridded floor as discs
// lying in it (rays in its plane), every 13th point unoriented (a sphere), and
// coincident twins (a tie).
LargeVector<Surfel> room_surfels() {
  Rng rng(7);
  std::vector<Eigen::Vector3f> points, normals;
  std::vector<float> radii;
  for (int i = 0; i < 4000; ++i) {
    points.push_back(random_point(rng, 0.0f, 10.0f));
    normals.push_back(i % 13 == 0 ? Eigen::Vector3f::Zero() : random_point(rng, -1.0f, 1.0f));
    radii.push_back(static_cast<float>(0.05 + 0.1 * rng.uniform()));
  }
  for (int i = 0; i < 80; ++i) {
    for (int j = 0; j < 80; ++j) {
      points.emplace_back(i * 0.125f, j * 0.125f, 0.0f);
      normals.emplace_back(0.0f, 0.0f, 1.0f);
      radii.push_back(0.09f);
    }
  }
  points.push_back(points[17]);
  normals.push_back(normals[17]);
  radii.push_back(radii[17]);
  return make_surfels(points, normals, radii);
}

const std::vector<Eigen::Vector3f> kViewpoints = {
    {2.0f, 3.0f, 1.5f}, {7.0f, 6.0f, 1.2f}, {5.0f, 5.0f, 2.5f}};

// Rays as the analyses make them, plus the edge cases, with the ignore ids.
struct Batch {
  std::vector<Ray> rays;
  std::vector<PrimitiveId> ignore;
};

// Shadow rays from random scene points to the viewpoints (sample-major, so
// viewpoints interleave), rays out of the viewpoints (viewpoint-major), random
// rays, a plan's rays from the viewpoints to points, then the edge cases.
Batch test_batch(std::size_t primitives, std::uint64_t seed) {
  Rng rng(seed);
  Batch batch;
  const auto add = [&](const Ray& ray, PrimitiveId ignore) {
    batch.rays.push_back(ray);
    batch.ignore.push_back(ignore);
  };
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3f p = random_point(rng, 0.0f, 10.0f);
    const auto own = static_cast<PrimitiveId>(rng.next() % primitives);
    for (const Eigen::Vector3f& vp : kViewpoints) add({p, vp - p, 1e-4f, 1.0f - 1e-4f}, own);
  }
  for (const Eigen::Vector3f& vp : kViewpoints) {
    for (int i = 0; i < 3000; ++i) {
      const double v = rng.uniform();  // in gcc's order, as random_point
      const Eigen::Vector3d d = sample_sphere_direction(rng.uniform(), v);
      add({vp, d.cast<float>(), 0.0f, std::numeric_limits<float>::infinity()}, kNoPrimitive);
      // A reversed interval now and then, in a packet with live lanes: what
      // compute_mesh_occlusion gives a sample too close to its viewpoint.
      if (i % 61 == 0) add({vp, d.cast<float>(), 1.0f, 0.0f}, kNoPrimitive);
    }
  }
  for (int i = 0; i < 3000; ++i) {
    Ray ray{random_point(rng, -1.0f, 11.0f), random_point(rng, -3.0f, 3.0f), 0.0f, 0.0f};
    ray.t_min = static_cast<float>(rng.uniform());
    ray.t_max = ray.t_min + static_cast<float>(4.0 * rng.uniform());
    add(ray, static_cast<PrimitiveId>(i % primitives));
  }
  // A plan's rays: from each viewpoint to scene points, one after another (a
  // packet of one origin, its rays loaded whole), ending short of the point
  // with the point's own id ignored.
  for (const Eigen::Vector3f& vp : kViewpoints) {
    for (int i = 0; i < 1000; ++i) {
      const Eigen::Vector3f p = random_point(rng, 0.0f, 10.0f);
      add({vp, p - vp, 0.0f, 0.999f}, static_cast<PrimitiveId>(rng.next() % primitives));
    }
  }
  // From one point of the floor's grid along the axes and the diagonals (zero
  // components, inverse directions of 1e30, from one origin), three lengths each.
  for (const float length : {0.5f, 2.0f, 20.0f}) {
    for (int i = 0; i < 27; ++i) {
      const Eigen::Vector3f d(static_cast<float>(i % 3 - 1), static_cast<float>(i / 3 % 3 - 1),
                              static_cast<float>(i / 9 - 1));
      add({{2.5f, 2.5f, 0.0f}, length * d, 0.0f, 1.0f}, kNoPrimitive);
    }
  }
  const float inf = std::numeric_limits<float>::infinity();
  // In the floor plane and in the wall plane, along the grid's edges and across it.
  add({{0.0f, 2.5f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.0f, inf}, kNoPrimitive);
  add({{-1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, 0.0f, inf}, kNoPrimitive);
  add({{10.0f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}, 0.0f, inf}, kNoPrimitive);
  // Axis-aligned from outside, straight onto the floor and the wall; one ends
  // exactly on the floor (hit at t_max), one just short of it.
  add({{3.3f, 4.4f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, inf}, kNoPrimitive);
  add({{3.3f, 4.4f, 5.0f}, {0.0f, 0.0f, -5.0f}, 0.0f, 1.0f}, kNoPrimitive);
  add({{3.3f, 4.4f, 5.0f}, {0.0f, 0.0f, -5.0f}, 0.0f, 0.99f}, kNoPrimitive);
  add({{12.0f, 2.0f, 2.0f}, {-1.0f, 0.0f, 0.0f}, 0.0f, inf}, kNoPrimitive);
  // Zero-length direction; empty, reversed and point-like intervals.
  add({{5.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.0f, 1.0f}, kNoPrimitive);
  add({{5.0f, 5.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 3.0f, 2.0f}, kNoPrimitive);
  add({{5.0f, 5.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 5.0f, 5.0f}, kNoPrimitive);
  return batch;
}

// Every traversal this machine can run.
std::vector<OctreeTraversal> traversals() {
  std::vector<OctreeTraversal> all;
  for (const OctreeTraversal traversal :
       {OctreeTraversal::kSingle, OctreeTraversal::kAuto, OctreeTraversal::kPacketSse2,
        OctreeTraversal::kPacketAvx2, OctreeTraversal::kPacketAvx512,
        OctreeTraversal::kPacketAvx2Wide}) {
    if (cpu_supports(traversal)) all.push_back(traversal);
  }
  return all;
}

// Shapes: a std::vector or a LargeVector of them (both octree constructors).
template <class Shapes>
void expect_batches_match_brute_force(const Shapes& shapes, const Batch& batch,
                                      OctreeOptions options) {
  using Shape = typename Shapes::value_type;
  // The reference, once: brute force over every shape, ray by ray.
  std::vector<std::optional<Hit>> expected(batch.rays.size());
  std::size_t hits = 0;
  for (std::size_t i = 0; i < batch.rays.size(); ++i) {
    expected[i] = brute_force_intersect(shapes, batch.rays[i], batch.ignore[i]);
    hits += expected[i] ? 1 : 0;
  }
  // Both outcomes are well represented, or the comparison means little.
  EXPECT_GT(hits, batch.rays.size() / 5);
  EXPECT_LT(hits, batch.rays.size() * 4 / 5);

  for (const OctreeTraversal traversal : traversals()) {
    options.traversal = traversal;
    const Octree<Shape> tree(shapes, options);
    // All rays, and a prefix whose length is not a multiple of the packet width.
    // Packets formed as the rays come (here interleaved, far from coherent)
    // answer as sorted ones do.
    struct Run {
      unsigned threads;
      BatchOrder order;
    };
    const Run runs[] = {{1u, BatchOrder::kSortByDirection},
                        {2u, BatchOrder::kSortByDirection},
                        {2u, BatchOrder::kAsGiven}};
    for (const std::size_t count : {batch.rays.size(), std::size_t{2053}}) {
      for (const auto [threads, order] : runs) {
        // Single rays have no packets to form (and kAuto is one of the others).
        if (order == BatchOrder::kAsGiven &&
            (traversal == OctreeTraversal::kSingle || traversal == OctreeTraversal::kAuto)) {
          continue;
        }
        std::vector<std::optional<Hit>> got(count);
        std::vector<std::uint8_t> blocked(count, 7);
        tree.intersect_batch(batch.rays.data(), count, batch.ignore.data(), got.data(), threads,
                             order);
        tree.occluded_batch(batch.rays.data(), count, batch.ignore.data(), blocked.data(), threads,
                            order);
        const std::string where =
            "traversal " + std::to_string(static_cast<int>(traversal)) + ", " +
            std::to_string(count) + " rays, " + std::to_string(threads) + " threads, " +
            (order == BatchOrder::kAsGiven ? "as given" : "sorted") + ", ray ";
        for (std::size_t i = 0; i < count; ++i) {
          ASSERT_EQ(expected[i].has_value(), got[i].has_value()) << where << i;
          ASSERT_EQ(blocked[i], expected[i] ? 1 : 0) << where << i;
          if (expected[i]) {
            ASSERT_EQ(expected[i]->t_hit, got[i]->t_hit) << where << i;
            ASSERT_EQ(expected[i]->primitive_id, got[i]->primitive_id) << where << i;
          }
        }
      }
    }
  }
}

TEST(OctreePackets, TrianglesMatchBruteForceRayByRay) {
  const std::vector<PackedTriangle> triangles = room_triangles();
  expect_batches_match_brute_force(triangles, test_batch(triangles.size(), 21), OctreeOptions{});
}

TEST(OctreePackets, TrianglesMatchBruteForceWithLeavesOfOne) {
  const std::vector<PackedTriangle> triangles = room_triangles();
  OctreeOptions options;
  options.max_leaf_size = 1;
  expect_batches_match_brute_force(triangles, test_batch(triangles.size(), 22), options);
}

TEST(OctreePackets, SpheresMatchBruteForceRayByRay) {
  const LargeVector<Sphere> spheres = room_spheres();
  expect_batches_match_brute_force(spheres, test_batch(spheres.size(), 23),
                                   sphere_octree_options());
}

TEST(OctreePackets, SurfelsMatchBruteForceRayByRay) {
  const LargeVector<Surfel> surfels = room_surfels();
  expect_batches_match_brute_force(surfels, test_batch(surfels.size(), 24),
                                   surfel_octree_options());
}

TEST(OctreePackets, TiesGoToTheLowerIdInEveryTraversal) {
  // Two identical triangles: every ray through them hits both at the same t.
  const Triangle tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<PackedTriangle> twins = pack_triangles({tri, tri, tri});
  std::vector<Ray> rays;
  Rng rng(3);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3f target(static_cast<float>(0.45 * rng.uniform()),
                                 static_cast<float>(0.45 * rng.uniform()), 0.0f);
    const Eigen::Vector3f origin = random_point(rng, -2.0f, 2.0f) + Eigen::Vector3f(0, 0, 3);
    rays.push_back({origin, target - origin, 0.0f, 2.0f});
  }
  std::vector<PrimitiveId> ignore(rays.size(), 0);  // the lowest twin is skipped
  for (const OctreeTraversal traversal : traversals()) {
    OctreeOptions options;
    options.traversal = traversal;
    options.max_leaf_size = 1;  // the twins end up in different leaves
    const TriangleOctree tree(twins, options);
    std::vector<std::optional<Hit>> hits(rays.size());
    tree.intersect_batch(rays.data(), rays.size(), ignore.data(), hits.data(), 1);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      ASSERT_TRUE(hits[i].has_value()) << i;
      EXPECT_EQ(hits[i]->primitive_id, 1u) << i;
      EXPECT_EQ(hits[i]->t_hit, brute_force_intersect(twins, rays[i], 0)->t_hit) << i;
    }
  }
}

TEST(OctreePackets, RefusesATraversalTheCpuCannotRun) {
  for (const OctreeTraversal traversal :
       {OctreeTraversal::kPacketSse2, OctreeTraversal::kPacketAvx2, OctreeTraversal::kPacketAvx512,
        OctreeTraversal::kPacketAvx2Wide}) {
    if (cpu_supports(traversal)) continue;
    OctreeOptions options;
    options.traversal = traversal;
    EXPECT_THROW(
        TriangleOctree(pack_triangles({Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}), options),
        std::invalid_argument);
  }
}

TEST(OctreePackets, NanIntervalsNeverHit) {
  // No t satisfies t_min <= t <= t_max when either bound is NaN (brute force's
  // kernel alone would let a NaN t_min through, so it is not the reference here).
  const std::vector<PackedTriangle> triangles = room_triangles();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Ray> rays;
  for (int i = 0; i < 20; ++i) {
    rays.push_back({{5.0f, 5.0f, 5.0f}, {0.01f * i, 0.0f, -1.0f}, nan, 9.0f});
    rays.push_back({{5.0f, 5.0f, 5.0f}, {0.0f, 0.01f * i, -1.0f}, 0.0f, nan});
  }
  for (const OctreeTraversal traversal : traversals()) {
    OctreeOptions options;
    options.traversal = traversal;
    const TriangleOctree tree(triangles, options);
    std::vector<std::optional<Hit>> hits(rays.size(), Hit{});
    std::vector<std::uint8_t> blocked(rays.size(), 1);
    tree.intersect_batch(rays.data(), rays.size(), nullptr, hits.data(), 1);
    tree.occluded_batch(rays.data(), rays.size(), nullptr, blocked.data(), 1);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      EXPECT_FALSE(hits[i].has_value()) << i;
      EXPECT_EQ(blocked[i], 0) << i;
      // Each of these rays would hit the floor with a finite interval.
      Ray finite = rays[i];
      finite.t_min = 0.0f;
      finite.t_max = 9.0f;
      EXPECT_TRUE(tree.occluded(finite)) << i;
    }
  }
}

TEST(OctreePackets, EmptyTreeAndEmptyBatch) {
  for (const OctreeTraversal traversal : traversals()) {
    OctreeOptions options;
    options.traversal = traversal;
    const TriangleOctree empty(std::vector<PackedTriangle>{}, options);
    const Ray ray{{0, 0, 0}, {1, 0, 0}, 0.0f, 1.0f};
    std::optional<Hit> hit = Hit{};
    std::uint8_t blocked = 1;
    empty.intersect_batch(&ray, 1, nullptr, &hit, 1);
    empty.occluded_batch(&ray, 1, nullptr, &blocked, 1);
    EXPECT_FALSE(hit.has_value());
    EXPECT_EQ(blocked, 0);
    empty.occluded_batch(nullptr, 0, nullptr, nullptr, 2);  // nothing to do, no crash
  }
}

}  // namespace
}  // namespace occlusion
