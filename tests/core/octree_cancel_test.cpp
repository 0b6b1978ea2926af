// Building an octree over millions of shapes takes seconds; a cancel stops
// it within a few nodes, before or during the build, with Cancelled.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "occlusion/core/random.hpp"
#include "occlusion/core/sphere_octree.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Four million points scattered in a 10 m cube: a build long enough (about
// 0.6 s in Release) that the scheduler's hiccups on a loaded machine, tens of
// milliseconds, are small beside the margins below.
LargeVector<Sphere> four_million_spheres() {
  Rng random(7);
  std::vector<Eigen::Vector3f> points(4'000'000);
  for (auto& p : points) {
    p = Eigen::Vector3f(static_cast<float>(10.0 * random.uniform()),
                        static_cast<float>(10.0 * random.uniform()),
                        static_cast<float>(10.0 * random.uniform()));
  }
  return make_spheres(points, 0.01f);
}

TEST(OctreeCancel, CancelledBeforeTheBuildBuildsNothing) {
  std::atomic<bool> cancel{true};
  Progress progress;
  progress.cancel = &cancel;
  EXPECT_THROW(SphereOctree(std::vector<Sphere>{}, sphere_octree_options(), progress), Cancelled);
  const std::vector<PackedTriangle> triangles =
      pack_triangles({Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  EXPECT_THROW(TriangleOctree(triangles, {}, progress), Cancelled);
  cancel = false;
  EXPECT_EQ(TriangleOctree(triangles, {}, progress).size(), 1u);
}

TEST(OctreeCancel, CancelStopsAFourMillionPointBuildPromptly) {
  // The caller's copy of the shapes is made before each clock starts: 64 MB
  // of fresh pages cost about as much as a third of the build on a VM.
  const LargeVector<Sphere> spheres = four_million_spheres();
  LargeVector<Sphere> copy = spheres;
  auto start = Clock::now();
  const SphereOctree full(std::move(copy), sphere_octree_options());
  const double full_seconds = seconds_since(start);
  ASSERT_GT(full.stats().inner_nodes, 10'000u);

  std::atomic<bool> cancel{true};
  Progress progress;
  progress.cancel = &cancel;
  copy = spheres;
  start = Clock::now();
  EXPECT_THROW(SphereOctree(std::move(copy), sphere_octree_options(), progress), Cancelled);
  const double before_seconds = seconds_since(start);
  EXPECT_LT(before_seconds, 0.25 * full_seconds) << "full build " << full_seconds << " s";

  // Cancelled a quarter of the way in: stops well before the end (a ratio of
  // the same build on the same machine, with half the build as margin for the
  // canceller's wake-up and the unwinding).
  cancel = false;
  const double delay = 0.25 * full_seconds;
  copy = spheres;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    cancel = true;
  });
  start = Clock::now();
  EXPECT_THROW(SphereOctree(std::move(copy), sphere_octree_options(), progress), Cancelled);
  const double during_seconds = seconds_since(start);
  canceller.join();
  EXPECT_LT(during_seconds, delay + 0.5 * full_seconds) << "full build " << full_seconds << " s";
}

}  // namespace
}  // namespace occlusion
