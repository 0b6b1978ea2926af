// Point-cloud occlusion in a closed box room of grid points: openings of any
// shape, and the exterior-structure variant (thesis 3.3.3, 3.3.5).
#include <gtest/gtest.h>

#include <cmath>

#include "occlusion/analysis/cloud_occlusion.hpp"
#include "support/cloud_scenes.hpp"

namespace occlusion {
namespace {

// The room [0, 4] x [0, 4] x [0, 3] with grid nodes 0.025 apart. Every point of
// a wall is within 0.025 / sqrt(2) = 0.018 of a node, and a ray passes a node
// no farther than its crossing point is from it, so with r = 0.02 the walls
// have no gaps. The wall x = 4 faces the viewpoint square on, 2 m away, with
// its foot point at (y, z) = (2, 1.5).
constexpr double kStep = 0.025;
constexpr double kRadius = 0.02;
constexpr int kNx = 160, kNy = 160, kNz = 120;
const Eigen::Vector3d kViewpoint(2, 2, 1.5);
constexpr int kRoomLabel = 0, kTableLabel = 1;

// An L cut into the wall x = 4, in grid indices (j along y, k along z):
// arm A = [1.5, 2.5] x [1.0, 1.5], arm B = [1.5, 2.0] x [1.5, 2.5]. Nodes on the
// L's boundary stay, so the hole is exactly the open L.
bool inside_l(int j, int k) {
  return (60 < j && j < 100 && 40 < k && k < 60) || (60 < j && j < 80 && 40 < k && k < 100);
}
// A square [1.75, 2.25] x [1.25, 1.75] cut into the same wall.
bool inside_square(int j, int k) {
  return 70 < j && j < 90 && 50 < k && k < 70;
}

PointCloud room(bool (*hole)(int, int)) {
  PointCloud cloud;
  testing::KeepNode keep = nullptr;
  if (hole != nullptr) keep = [hole](int j, int k) { return !hole(j, k); };
  testing::add_box_grid(cloud, kNx, kNy, kNz, kStep, kRoomLabel, keep);
  return cloud;
}

// A cabinet front: a vertical square of points at x = 3 spanning
// [1.5, 2.5] x [1.0, 2.0], which covers the square hole's cone (half as wide
// there as at the wall).
void add_cabinet(PointCloud& cloud) {
  testing::add_grid(cloud, {3, 1.5, 1.0}, Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), 40,
                    40, kStep, kTableLabel);
}

PlanarPolygon wall_polygon(const std::vector<Eigen::Vector2d>& yz) {
  std::vector<Eigen::Vector3d> boundary;
  for (const auto& p : yz) boundary.emplace_back(4.0, p.x(), p.y());
  return PlanarPolygon(boundary);
}

CloudOcclusionOptions room_options(std::size_t rays, DirectionSampling sampling) {
  CloudOcclusionOptions options;
  options.point_radius = kRadius;
  options.num_rays_per_vp = rays;
  options.sampling = sampling;
  options.seed = 3;
  return options;
}

// Where a direction from the viewpoint crosses the wall x = 4, as (y, z).
std::optional<Eigen::Vector2d> wall_crossing(const Eigen::Vector3d& d) {
  if (d.x() <= 0) return std::nullopt;
  const double t = (4.0 - kViewpoint.x()) / d.x();
  return Eigen::Vector2d(kViewpoint.y() + t * d.y(), kViewpoint.z() + t * d.z());
}

std::size_t count_crossings(const CloudOcclusionOptions& options, double y0, double y1, double z0,
                            double z1) {
  const SphereDirections directions(options.sampling, options.num_rays_per_vp, options.seed, 0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const auto q = wall_crossing(directions(i));
    if (q && q->x() >= y0 && q->x() <= y1 && q->y() >= z0 && q->y() <= z1) ++count;
  }
  return count;
}

TEST(CloudRoom, ClosedRoomHasNoOcclusion) {
  PointCloud cloud = room(nullptr);
  add_cabinet(cloud);
  const auto result = compute_cloud_occlusion(cloud, {kViewpoint, {0.5, 3.5, 2.5}}, {},
                                              room_options(20000, DirectionSampling::kUniform));
  EXPECT_EQ(result.occlusion_rays, 0u);
  EXPECT_EQ(result.hits, 40000u);
}

TEST(CloudRoom, ConcaveOpeningOfTheHoleShapeLetsEveryEscapeOut) {
  const PointCloud cloud = room(inside_l);
  const auto options = room_options(40000, DirectionSampling::kFibonacci);
  const auto bare = compute_cloud_occlusion(cloud, {kViewpoint}, {}, options);
  EXPECT_GT(bare.occlusion_rays, 0u);
  const PlanarPolygon l_shape =
      wall_polygon({{1.5, 1.0}, {2.5, 1.0}, {2.5, 1.5}, {2.0, 1.5}, {2.0, 2.5}, {1.5, 2.5}});
  const auto covered = compute_cloud_occlusion(cloud, {kViewpoint}, {l_shape}, options);
  EXPECT_EQ(covered.occlusion_rays, 0u);
  // Every escape now leaves through the L. A few rays that graze a node at the
  // hole's edge cross the L's plane before they enter that node's sphere, so
  // they leave too: the exits are at least the escapes.
  EXPECT_GE(covered.through_openings, bare.occlusion_rays);
  EXPECT_LE(covered.through_openings, bare.occlusion_rays + bare.occlusion_rays / 100);
  EXPECT_EQ(covered.through_openings + covered.hits, covered.rays);
}

TEST(CloudRoom, OpeningOverOneArmLeavesTheOtherArmOccluding) {
  // A rectangle over arm A, reaching into the wall around it but not above
  // z = 1.5: the rays that still escape cross the wall inside arm B. The
  // walls' spheres narrow B: a ray through (y, z) is stopped by a node whose
  // offset w in the wall has |w| cos(incidence) <= r, so B shrunk by
  // e = r / cos(largest incidence over B) on its three wall sides lets rays
  // through, and nothing outside B does.
  const PointCloud cloud = room(inside_l);
  const PlanarPolygon arm_a = wall_polygon({{1.4, 0.9}, {2.6, 0.9}, {2.6, 1.5}, {1.4, 1.5}});
  const auto options = room_options(100000, DirectionSampling::kFibonacci);
  const auto result = compute_cloud_occlusion(cloud, {kViewpoint}, {arm_a}, options);
  const double cos_incidence = 2.0 / std::sqrt(4.0 + 0.5 * 0.5 + 1.0 * 1.0);
  const double e = kRadius / cos_incidence;
  const std::size_t sure = count_crossings(options, 1.5 + e, 2.0 - e, 1.5 + 1e-9, 2.5 - e);
  const std::size_t possible = count_crossings(options, 1.5, 2.0, 1.5, 2.5);
  EXPECT_GE(result.occlusion_rays, sure);
  EXPECT_LE(result.occlusion_rays, possible);
  EXPECT_LT(sure, possible);
  // The same bracket in solid angles: arm B spans u in [-0.5, 0], v in [0, 1]
  // around the foot point, at distance 2.
  const double whole = testing::rectangle_solid_angle(2, -0.5, 0, 0, 1) / (4 * M_PI);
  const double shrunk = testing::rectangle_solid_angle(2, -0.5 + e, -e, 0, 1 - e) / (4 * M_PI);
  EXPECT_GE(result.occlusion_level, shrunk - 2e-4);
  EXPECT_LE(result.occlusion_level, whole + 2e-4);
}

TEST(CloudRoom, InteriorExteriorRatioIsThePointCountRatio) {
  PointCloud cloud = room(nullptr);
  const std::size_t room_points = cloud.size();
  add_cabinet(cloud);
  std::vector<bool> exterior(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) exterior[i] = cloud.labels[i] == kRoomLabel;
  EXPECT_DOUBLE_EQ(interior_exterior_ratio(exterior),
                   41.0 * 41.0 / static_cast<double>(room_points));
  EXPECT_EQ(room_points, 2u * 161 * 161 + 2u * 161 * 121 + 2u * 161 * 121);
}

TEST(CloudRoom, ExteriorOnlyCountsRaysTheInteriorWouldHaveStopped) {
  const auto options = room_options(20000, DirectionSampling::kUniform);
  const auto hole_alone = compute_cloud_occlusion(room(inside_square), {kViewpoint}, {}, options);
  EXPECT_GT(hole_alone.occlusion_rays, 0u);

  PointCloud cloud = room(inside_square);
  add_cabinet(cloud);
  std::vector<bool> exterior(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) exterior[i] = cloud.labels[i] == kRoomLabel;

  // Every point blocking: the cabinet stands in front of the whole hole.
  const auto all = compute_cloud_occlusion(cloud, {kViewpoint}, {}, options);
  EXPECT_EQ(all.occlusion_rays, 0u);

  auto exterior_options = options;
  exterior_options.blocking = exterior;
  const auto outer = compute_cloud_occlusion(cloud, {kViewpoint}, {}, exterior_options);
  EXPECT_EQ(outer.occlusion_rays, hole_alone.occlusion_rays);
  EXPECT_EQ(outer.hits, hole_alone.hits);
  EXPECT_EQ(outer.points, cloud.size());
  EXPECT_EQ(outer.blocking_points, hole_alone.points);
  EXPECT_EQ(outer.octree.primitives, hole_alone.points);
}

}  // namespace
}  // namespace occlusion
