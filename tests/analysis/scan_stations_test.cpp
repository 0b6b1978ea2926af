// Per-station answers of the scan (-fscan): how many stations see each point,
// the first that does, and what each station alone sees, judged against the
// truth: a plate in front of a wall seen by two stations (its two shadows
// worked out by hand), and a furnished room scanned by the virtual scanner
// from two stations, the mesh telling which station sees each return.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/analysis/virtual_scanner.hpp"
#include "support/cloud_scenes.hpp"
#include "support/mesh_truth.hpp"

namespace occlusion {
namespace {

// Every figure of a result adds up: the only-this-viewpoint counts, the
// points seen by several and those seen by none make up the cloud, and each
// viewpoint's count is the marginal of the per-point counts and firsts.
void expect_figures_add_up(const ScanResult& r, std::size_t viewpoints) {
  const std::size_t points = r.visible_count.size();
  ASSERT_EQ(r.first_viewpoint.size(), points);
  ASSERT_EQ(r.only_by_viewpoint.size(), viewpoints);
  const std::size_t only =
      std::accumulate(r.only_by_viewpoint.begin(), r.only_by_viewpoint.end(), std::size_t{0});
  EXPECT_EQ(only + r.seen_by_several + (points - r.visible_points), points);
  std::vector<std::size_t> only_first(viewpoints, 0);
  std::size_t several = 0, none = 0, counted = 0;
  for (std::size_t i = 0; i < points; ++i) {
    const std::uint16_t count = r.visible_count[i];
    const std::int32_t first = r.first_viewpoint[i];
    counted += count;
    if (count == 0) {
      EXPECT_EQ(first, -1) << i;
      ++none;
      continue;
    }
    ASSERT_GE(first, 1) << i;
    ASSERT_LE(first, static_cast<std::int32_t>(viewpoints)) << i;
    if (count == 1) ++only_first[static_cast<std::size_t>(first - 1)];
    if (count > 1) ++several;
  }
  EXPECT_EQ(only_first, r.only_by_viewpoint);
  EXPECT_EQ(several, r.seen_by_several);
  EXPECT_EQ(none, points - r.visible_points);
  EXPECT_EQ(std::accumulate(r.seen_by_viewpoint.begin(), r.seen_by_viewpoint.end(), std::size_t{0}),
            counted);
}

using Scene = testing::PlateBeforeWall;

TEST(ScanStations, APlateBeforeAWallCastsOneShadowPerStation) {
  const PointCloud cloud = Scene::cloud();
  ScanOptions options;
  options.point_radius = Scene::kStep;
  const ScanResult r = scan_cloud(cloud, {Scene::a(), Scene::b()}, options);
  expect_figures_add_up(r, 2);
  // The spheres widen a shadow by about 2 r and the grids are not aligned:
  // three spacings either side of a shadow's edge are left open.
  const double band = 3 * Scene::kStep;
  std::size_t decided = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Scene::Seen truth = Scene::expected(cloud.positions[i], cloud.labels[i], band);
    if (truth.count < 0) continue;
    ++decided;
    EXPECT_EQ(r.visible_count[i], truth.count) << cloud.positions[i].transpose();
    EXPECT_EQ(r.first_viewpoint[i], truth.first) << cloud.positions[i].transpose();
  }
  EXPECT_GT(decided, cloud.size() * 8 / 10);
  EXPECT_EQ(r.visible_points, cloud.size() - Scene::kBehindPoints);
  // A shadow is 0.8 x 0.8 m: 40 x 40 wall cells, give or take the band.
  for (std::size_t v = 0; v < 2; ++v) {
    EXPECT_GE(r.only_by_viewpoint[v], 34u * 34u) << v;
    EXPECT_LE(r.only_by_viewpoint[v], 46u * 46u) << v;
  }
  // Mirror images: the two stations alone see as much, within the band.
  EXPECT_NEAR(static_cast<double>(r.only_by_viewpoint[0]),
              static_cast<double>(r.only_by_viewpoint[1]), 80.0);
  // The first station is the first in the order given.
  const ScanResult swapped = scan_cloud(cloud, {Scene::b(), Scene::a()}, options);
  EXPECT_EQ(swapped.visible_count, r.visible_count);
  EXPECT_EQ(swapped.only_by_viewpoint[0], r.only_by_viewpoint[1]);
  EXPECT_EQ(swapped.only_by_viewpoint[1], r.only_by_viewpoint[0]);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (r.visible_count[i] == 1) {
      EXPECT_EQ(swapped.first_viewpoint[i], 3 - r.first_viewpoint[i]);
    }
  }
}

TEST(ScanStations, ASimulatedTwoStationScanAgreesWithTheMeshPerStation) {
  const TriangleMesh room = testing::furnished_room();
  const std::vector<ScannerStation> stations{{"s1", {2.5, 3.0, 1.5}}, {"s2", {4.2, 1.2, 1.2}}};
  LaserScannerModel laser;
  laser.azimuth_step_deg = 1.0;
  laser.elevation_step_deg = 1.0;
  SimulationOptions simulation;
  simulation.seed = 5;
  simulation.noise = false;
  const SimulatedScan scan = simulate_scan(room, stations, laser, simulation);
  const SurfelEstimate surfels = estimate_surfels(scan.cloud, SurfelOptions{});
  ScanOptions options;
  options.surfels = &surfels;
  const ScanResult r =
      scan_cloud(scan.cloud, {stations[0].position, stations[1].position}, options);
  expect_figures_add_up(r, 2);

  // The truth: which station the mesh lets see the surface point each beam hit.
  testing::SampledCloud truth;
  truth.cloud.positions = scan.true_points;
  truth.face = scan.faces;
  const auto by_a = testing::mesh_visibility(room, truth, stations[0].position);
  const auto by_b = testing::mesh_visibility(room, truth, stations[1].position);
  const std::size_t points = scan.cloud.size();
  std::size_t same = 0, own = 0;
  std::vector<std::size_t> only_truth(2, 0);
  for (std::size_t i = 0; i < points; ++i) {
    const int count = (by_a[i] != 0) + (by_b[i] != 0);
    const std::int32_t first = by_a[i] ? 1 : (by_b[i] ? 2 : -1);
    if (count == 1) ++only_truth[static_cast<std::size_t>(first - 1)];
    same += r.visible_count[i] == count && r.first_viewpoint[i] == first;
    // A return is seen by its own station: the first is station 1 or the count is 2.
    const bool by_own = scan.cloud.station_ids[i] == 0
                            ? r.first_viewpoint[i] == 1
                            : r.visible_count[i] == 2 || r.first_viewpoint[i] == 2;
    own += by_own;
  }
  const double n = static_cast<double>(points);
  std::printf(
      "two stations, %zu points: agree %.4f, own %.4f; only s1 %.4f (mesh %.4f), only s2 "
      "%.4f (mesh %.4f)\n",
      points, same / n, own / n, r.only_by_viewpoint[0] / n, only_truth[0] / n,
      r.only_by_viewpoint[1] / n, only_truth[1] / n);
  EXPECT_GE(own / n, 0.995);
  EXPECT_GE(same / n, 0.96);
  for (std::size_t v = 0; v < 2; ++v) {
    EXPECT_NEAR(r.only_by_viewpoint[v] / n, only_truth[v] / n, 0.015) << v;
    EXPECT_GT(only_truth[v], points / 20) << "each station alone sees a part of the room";
  }
}

}  // namespace
}  // namespace occlusion
