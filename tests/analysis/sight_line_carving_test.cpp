// Lines of sight a scan proves free (analysis/sight_line_carving): a plate
// 1 m in front of a wall, station 1 at the origin seeing the plate and the
// wall around its shadow, station 2 between them seeing the wall in the
// shadow. Worked by hand: the plate's points are 1 cm apart, so its edge
// discs reach about 1.25 cm past its edge at x = 1; a wall point 1 cm beyond
// the shadow's edge at x = 2 is seen past the plate's edge by 0.5 cm, inside
// that overhang. Carving clears every line of sight the stations recorded and
// leaves the plate hiding its whole shadow.

#include "occlusion/analysis/sight_line_carving.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"

namespace occlusion {
namespace {

constexpr double kPlateHalf = 0.2;  // the plate spans y, z in [-0.2, 0.2] at x = 1
constexpr double kWallX = 2.0;

struct PlateAndWall {
  PointCloud cloud;
  std::vector<bool> in_shadow;  // a wall point the plate hides from station 1
};

PlateAndWall plate_and_wall() {
  PlateAndWall scene;
  PointCloud& cloud = scene.cloud;
  cloud.stations = {{"station_1", {}}, {"station_2", {}}};
  cloud.stations[1].frame.origin = Eigen::Vector3d(1.5, 0.0, 0.0);
  for (int j = -20; j <= 20; ++j) {
    for (int k = -20; k <= 20; ++k) {
      cloud.positions.emplace_back(1.0f, 0.01f * j, 0.01f * k);
      cloud.station_ids.push_back(0);
      scene.in_shadow.push_back(false);
    }
  }
  // Rows at odd centimetres: none on the shadow's edge (|y| = 0.4 at x = 2).
  for (int j = -50; j < 50; ++j) {
    for (int k = -50; k < 50; ++k) {
      const double y = 0.01 + 0.02 * j, z = 0.01 + 0.02 * k;
      const bool shadow = std::max(std::abs(y), std::abs(z)) < kWallX * kPlateHalf;
      cloud.positions.emplace_back(static_cast<float>(kWallX), static_cast<float>(y),
                                   static_cast<float>(z));
      cloud.station_ids.push_back(shadow ? 1 : 0);
      scene.in_shadow.push_back(shadow);
    }
  }
  return scene;
}

std::vector<std::uint16_t> seen_from(const PointCloud& cloud, const SurfelEstimate& estimate,
                                     const Eigen::Vector3d& viewpoint) {
  ScanOptions options;
  options.surfels = &estimate;
  return scan_cloud(cloud, {viewpoint}, options).visible_count;
}

std::size_t own_points_hidden(const PointCloud& cloud, const SurfelEstimate& estimate) {
  std::size_t hidden = 0;
  for (std::size_t s = 0; s < cloud.stations.size(); ++s) {
    const std::vector<std::uint16_t> seen =
        seen_from(cloud, estimate, cloud.stations[s].frame.origin);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      hidden += cloud.station_ids[i] == static_cast<std::int32_t>(s) && seen[i] == 0;
    }
  }
  return hidden;
}

TEST(SightLineCarving, ThePlatesEdgeDiscsNoLongerHideTheWallJustPastItsShadow) {
  const PlateAndWall scene = plate_and_wall();
  SurfelOptions uncarved;
  uncarved.carve_sight_lines = false;
  const SurfelEstimate before = estimate_surfels(scene.cloud, uncarved);
  // The overhang the carving is for: without it station 1 loses its points
  // along the shadow's edge (four sides of 40 rows and more).
  EXPECT_GE(own_points_hidden(scene.cloud, before), 80u);

  const SurfelEstimate after = estimate_surfels(scene.cloud, SurfelOptions{});
  EXPECT_EQ(own_points_hidden(scene.cloud, after), 0u);
  EXPECT_GE(after.carving.blocked, 80u);
  EXPECT_GT(after.carving.shrunk, 0u);
  // Only the plate's rim shrank: its discs within 2 cm of the edge.
  std::size_t shrunk = 0;
  for (std::size_t i = 0; i < scene.cloud.size(); ++i) {
    if (after.surfels[i].radius == before.surfels[i].radius) continue;
    ++shrunk;
    const Eigen::Vector3f p = scene.cloud.positions[i];
    EXPECT_FLOAT_EQ(p.x(), 1.0f) << "a wall disc shrank at " << p.transpose();
    EXPECT_GE(std::max(std::abs(p.y()), std::abs(p.z())), kPlateHalf - 0.02 - 1e-6)
        << "a disc inside the plate shrank at " << p.transpose();
    EXPECT_LT(after.surfels[i].radius, before.surfels[i].radius);
  }
  EXPECT_EQ(shrunk, after.carving.shrunk);

  // The other direction: the plate still hides all of its shadow from station 1.
  const std::vector<std::uint16_t> seen =
      seen_from(scene.cloud, after, scene.cloud.stations[0].frame.origin);
  std::size_t shadow = 0;
  for (std::size_t i = 0; i < scene.cloud.size(); ++i) {
    if (!scene.in_shadow[i]) continue;
    ++shadow;
    EXPECT_EQ(seen[i], 0u) << "the plate's shadow shows at "
                           << scene.cloud.positions[i].transpose();
  }
  EXPECT_EQ(shadow, 1600u);  // 40 x 40 rows
}

TEST(SightLineCarving, AStationThatCannotHaveSeenItsPointsIsNotCarved) {
  PlateAndWall scene = plate_and_wall();
  // Behind the wall: its lines to the plate and to the wall's other points
  // cross the wall, which a pose error looks like.
  scene.cloud.stations[0].frame.origin = Eigen::Vector3d(3.0, 0.1, 0.1);
  SurfelOptions uncarved;
  uncarved.carve_sight_lines = false;
  const SurfelEstimate before = estimate_surfels(scene.cloud, uncarved);
  const SurfelEstimate after = estimate_surfels(scene.cloud, SurfelOptions{});
  ASSERT_EQ(after.carving.implausible.size(), 1u);
  EXPECT_EQ(after.carving.implausible[0].name, "station_1");
  EXPECT_GT(after.carving.implausible[0].blocked_share, kMaxBlockedShare);
  // The report counts its blocked lines, though none was carved.
  std::size_t own = 0;
  for (const std::int32_t id : scene.cloud.station_ids) own += id == 0;
  EXPECT_GE(static_cast<double>(after.carving.blocked),
            after.carving.implausible[0].blocked_share * static_cast<double>(own) - 0.5);
  EXPECT_EQ(after.carving.still_blocked, after.carving.blocked);
  EXPECT_EQ(after.carving.shrunk, 0u);
  for (std::size_t i = 0; i < scene.cloud.size(); ++i) {
    ASSERT_EQ(after.surfels[i].radius, before.surfels[i].radius);
  }
}

TEST(SightLineCarving, ACloudWithoutStationsIsLeftAsItIs) {
  PlateAndWall scene = plate_and_wall();
  scene.cloud.stations.clear();
  scene.cloud.station_ids.clear();
  SurfelOptions uncarved;
  uncarved.carve_sight_lines = false;
  const SurfelEstimate before = estimate_surfels(scene.cloud, uncarved);
  SurfelEstimate after = estimate_surfels(scene.cloud, SurfelOptions{});
  EXPECT_EQ(after.carving.shrunk, 0u);
  EXPECT_EQ(after.carving.blocked, 0u);
  for (std::size_t i = 0; i < scene.cloud.size(); ++i) {
    ASSERT_EQ(after.surfels[i].radius, before.surfels[i].radius);
  }
  const SightLineCarving carving = carve_sight_lines(scene.cloud, after, 0);
  EXPECT_EQ(carving.lines, 0u);
}

}  // namespace
}  // namespace occlusion
