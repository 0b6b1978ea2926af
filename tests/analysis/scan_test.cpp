#include "occlusion/analysis/scan.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "support/cloud_scenes.hpp"

namespace occlusion {
namespace {

// The cube room [0, 2]^3 sampled at cell centres 0.02 apart (no point on an
// edge), with r = 0.02, a plate of points [0.8, 1.2]^2 at z = 0.5 and the
// viewpoint at the centre (1, 1, 1). By similar triangles the plate's shadow on
// the floor is [0.6, 1.4]^2; nothing else is hidden.
//
// Every surface point is seen from the centre at an elevation of at least
// 35.3 degrees (the corners). A neighbour on the same surface can only block
// within r / sin(elevation) = 1.73 r of the point, inside the default
// self-tolerance of 2 r, so no point hides itself.
constexpr double kStep = 0.02;
constexpr double kRadius = 0.02;
constexpr int kCells = 100;
const Eigen::Vector3d kCentre(1, 1, 1);

enum Part : std::int32_t { kFloor, kCeiling, kWall, kPlate };

void add_face(PointCloud& cloud, const Eigen::Vector3d& corner, const Eigen::Vector3d& a,
              const Eigen::Vector3d& b, Part part) {
  testing::add_grid(cloud, corner + 0.5 * kStep * (a + b), a, b, kCells - 1, kCells - 1, kStep,
                    part);
}

const PointCloud& room_with_plate() {
  static const PointCloud cloud = [] {
    PointCloud c;
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                          z = Eigen::Vector3d::UnitZ();
    add_face(c, {0, 0, 0}, x, y, kFloor);
    add_face(c, {0, 0, 2}, x, y, kCeiling);
    add_face(c, {0, 0, 0}, y, z, kWall);
    add_face(c, {2, 0, 0}, y, z, kWall);
    add_face(c, {0, 0, 0}, x, z, kWall);
    add_face(c, {0, 2, 0}, x, z, kWall);
    testing::add_grid(c, {0.8, 0.8, 0.5}, x, y, 20, 20, kStep, kPlate);
    return c;
  }();
  return cloud;
}

ScanOptions scan_options() {
  ScanOptions options;
  options.point_radius = kRadius;
  return options;
}

// Distance of a floor point from the shadow's centre, in the max norm.
double shadow_offset(const Eigen::Vector3f& p) {
  return std::max(std::abs(p.x() - 1.0), std::abs(p.y() - 1.0));
}

TEST(Scan, PlateShadowOnTheFloorFollowsSimilarTriangles) {
  const PointCloud& cloud = room_with_plate();
  const auto result = scan_cloud(cloud, {kCentre}, scan_options());
  ASSERT_EQ(result.visible_count.size(), cloud.size());
  // The plate's spheres widen its shadow by about 2 r, and its grid and the
  // floor's are not aligned: a band of three spacings either side is left open.
  const double band = 3 * kStep;
  std::size_t unseen = 0, in_band = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const bool seen = result.visible_count[i] > 0;
    unseen += seen ? 0 : 1;
    if (cloud.labels[i] != kFloor) {
      EXPECT_TRUE(seen) << "point " << i << " part " << cloud.labels[i];
      continue;
    }
    const double offset = shadow_offset(cloud.positions[i]);
    if (offset < 0.4 - band) {
      EXPECT_FALSE(seen) << "floor point in the shadow " << cloud.positions[i].transpose();
    } else if (offset > 0.4 + band) {
      EXPECT_TRUE(seen) << "floor point out of the shadow " << cloud.positions[i].transpose();
    } else {
      ++in_band;
    }
  }
  // 40 x 40 floor cells lie in the shadow; the band decides at most the rest.
  EXPECT_GE(unseen, 34u * 34u);
  EXPECT_LE(unseen, 34u * 34u + in_band);
  EXPECT_EQ(result.visible_points, cloud.size() - unseen);
  EXPECT_DOUBLE_EQ(result.visible_fraction,
                   static_cast<double>(result.visible_points) / static_cast<double>(cloud.size()));
  ASSERT_EQ(result.seen_by_viewpoint.size(), 1u);
  EXPECT_EQ(result.seen_by_viewpoint[0], result.visible_points);
  EXPECT_EQ(result.octree.primitives, cloud.size());
}

TEST(Scan, ViewpointInsideAPointStillSees) {
  // One point exactly at the viewpoint and one 0.01 off it: the viewpoint is
  // inside both spheres, which must not hide anything.
  const PointCloud& base = room_with_plate();
  PointCloud cloud = base;
  cloud.positions.push_back(kCentre.cast<float>());
  cloud.positions.push_back(Eigen::Vector3f(1.01f, 1.0f, 1.0f));
  cloud.labels.push_back(kPlate);
  cloud.labels.push_back(kPlate);
  const auto alone = scan_cloud(base, {kCentre}, scan_options());
  const auto crowded = scan_cloud(cloud, {kCentre}, scan_options());
  const std::vector<std::uint16_t> original(crowded.visible_count.begin(),
                                            crowded.visible_count.begin() + base.size());
  EXPECT_EQ(original, alone.visible_count);
  EXPECT_EQ(crowded.visible_count[base.size()], 1);
  EXPECT_EQ(crowded.visible_count[base.size() + 1], 1);
}

TEST(Scan, TwoViewpointsAddUp) {
  // The second viewpoint sits just under the plate: it sees the floor the
  // first misses and the plate hides most of the ceiling from it.
  const PointCloud& cloud = room_with_plate();
  const Eigen::Vector3d low(1, 1, 0.4);
  const auto a = scan_cloud(cloud, {kCentre}, scan_options());
  const auto b = scan_cloud(cloud, {low}, scan_options());
  const auto both = scan_cloud(cloud, {kCentre, low}, scan_options());
  std::size_t union_count = 0, twice = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    ASSERT_EQ(both.visible_count[i], a.visible_count[i] + b.visible_count[i]) << i;
    union_count += both.visible_count[i] > 0 ? 1 : 0;
    twice += both.visible_count[i] == 2 ? 1 : 0;
    if (cloud.labels[i] == kFloor && shadow_offset(cloud.positions[i]) < 0.3) {
      EXPECT_EQ(both.visible_count[i], 1) << "seen from below the plate only";
    }
  }
  EXPECT_EQ(both.visible_points, union_count);
  EXPECT_GT(twice, cloud.size() / 10);
  EXPECT_LT(twice, both.visible_points);
  EXPECT_EQ(both.seen_by_viewpoint,
            std::vector<std::size_t>({a.seen_by_viewpoint[0], b.seen_by_viewpoint[0]}));
  EXPECT_GT(both.visible_points, a.visible_points);
}

TEST(Scan, WithoutSelfToleranceASurfaceHidesItself) {
  // Neighbours on the same surface overlap the point's sphere: with nothing
  // ignored near the point they block its ray at any angle.
  const PointCloud& cloud = room_with_plate();
  auto options = scan_options();
  const auto tolerant = scan_cloud(cloud, {kCentre}, options);
  options.self_tolerance = 0;
  const auto strict = scan_cloud(cloud, {kCentre}, options);
  EXPECT_LT(strict.visible_points, tolerant.visible_points / 2);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    ASSERT_LE(strict.visible_count[i], tolerant.visible_count[i]);
  }
}

TEST(Scan, DefaultToleranceHidesSurfacesSeenBelowThirtyDegrees) {
  // A floor seen from 0.5 above: a neighbour's sphere can reach the ray only
  // within r / sin(elevation) of the point, which exceeds the tolerance 2 r
  // below 30 degrees (1.2 m or more away, horizontally, at 0.5 m height: 22.6
  // degrees; within 0.75 m: 33.7 degrees).
  PointCloud floor;
  testing::add_grid(floor, {-1.5, -1.5, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 300,
                    300, 0.01);
  const Eigen::Vector3d eye(0, 0, 0.5);
  auto options = scan_options();
  const auto standard = scan_cloud(floor, {eye}, options);
  options.self_tolerance = 10 * kRadius;  // hides below 5.7 degrees only
  const auto lenient = scan_cloud(floor, {eye}, options);
  std::size_t near = 0, far = 0;
  for (std::size_t i = 0; i < floor.size(); ++i) {
    const double distance = floor.positions[i].head<2>().norm();
    if (distance < 0.75) {
      ++near;
      EXPECT_EQ(standard.visible_count[i], 1) << floor.positions[i].transpose();
    } else if (distance > 1.2) {
      ++far;
      EXPECT_EQ(standard.visible_count[i], 0) << floor.positions[i].transpose();
    }
  }
  EXPECT_GT(near, 1000u);
  EXPECT_GT(far, 1000u);
  EXPECT_EQ(lenient.visible_points, floor.size());
}

TEST(Scan, SameAnswerWhateverTheThreadsOrTheTree) {
  const PointCloud& cloud = room_with_plate();
  auto options = scan_options();
  options.threads = 1;
  const auto one = scan_cloud(cloud, {kCentre, {0.3, 1.7, 1.2}}, options);
  options.threads = 2;
  const auto two = scan_cloud(cloud, {kCentre, {0.3, 1.7, 1.2}}, options);
  EXPECT_EQ(one.visible_count, two.visible_count);
  EXPECT_EQ(one.seen_by_viewpoint, two.seen_by_viewpoint);

  PointCloud small;
  testing::add_grid(small, {0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 40, 40,
                    0.05);
  testing::add_grid(small, {0.5, 0.5, 0.5}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 10,
                    10, 0.05);
  options.point_radius = 0.04;
  const auto fast = scan_cloud(small, {{1, 1, 1}}, options);
  options.octree.enable_acceleration = false;
  const auto slow = scan_cloud(small, {{1, 1, 1}}, options);
  EXPECT_EQ(fast.visible_count, slow.visible_count);
  EXPECT_LT(fast.visible_points, small.size());
  EXPECT_EQ(slow.octree.leaves, 1u);
}

TEST(Scan, RejectsBadInput) {
  PointCloud cloud;
  testing::add_grid(cloud, {0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 3, 3,
                    0.1);
  const ScanOptions good = scan_options();
  EXPECT_THROW(scan_cloud(PointCloud{}, {kCentre}, good), std::invalid_argument);
  EXPECT_THROW(scan_cloud(cloud, {}, good), std::invalid_argument);
  EXPECT_THROW(scan_cloud(cloud, {{INFINITY, 0, 0}}, good), std::invalid_argument);
  EXPECT_THROW(scan_cloud(cloud, std::vector<Eigen::Vector3d>(65536, kCentre), good),
               std::invalid_argument);
  auto options = good;
  options.point_radius = -1;
  EXPECT_THROW(scan_cloud(cloud, {kCentre}, options), std::invalid_argument);
  options = good;
  options.self_tolerance = NAN;
  EXPECT_THROW(scan_cloud(cloud, {kCentre}, options), std::invalid_argument);
  PointCloud bad = cloud;
  bad.positions[2].z() = NAN;
  EXPECT_THROW(scan_cloud(bad, {kCentre}, good), std::invalid_argument);
}

TEST(Scan, CancelStopsWithCancelled) {
  std::atomic<bool> cancel{true};
  Progress progress;
  progress.cancel = &cancel;
  EXPECT_THROW(scan_cloud(room_with_plate(), {kCentre}, scan_options(), progress), Cancelled);
}

TEST(Scan, ReportsTracingProgressUpToOne) {
  std::size_t reports = 0;
  double last = -1;
  Progress progress;
  progress.report = [&](const std::string& stage, double fraction) {
    reports += stage == "tracing" ? 1 : 0;
    last = fraction;
  };
  scan_cloud(room_with_plate(), {kCentre, kCentre}, scan_options(), progress);  // 2 blocks
  EXPECT_GE(reports, 3u);
  EXPECT_DOUBLE_EQ(last, 1.0);
}

}  // namespace
}  // namespace occlusion
