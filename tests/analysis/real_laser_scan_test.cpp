// Real laser scans stored as their beams swept (analysis/beam_order): 3DTK's
// three stations (files/3dtk: a tilting SICK line scanner, 0.5 degree steps,
// ranges to 32 m, its no-return values written at 32.77 m) and PCL's room
// scan (files/pcl/room_scan1.pcd: about 1 degree steps, ranges rounded to
// 1 cm, a tenth of its returns from the scanner's own mount 10 cm below it).
// Every point was seen from its station, so -fscan from there keeps it.
// Before beam order both were left uncarved with a false warning of a wrong
// pose: 3DTK's stations kept 80.9, 83.5 and 84.4 %, the room scan 75.5 %.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

std::string repository_file(const std::string& path) {
  return std::string(OCCLUSION_SOURCE_DIR) + "/files/" + path;
}

// The share of its points a single-station scan keeps from its station.
double kept_from_its_station(const PointCloud& cloud, const SurfelEstimate& estimate) {
  ScanOptions options;
  options.surfels = &estimate;
  const ScanResult seen = scan_cloud(cloud, {cloud.stations.at(0).frame.origin}, options);
  std::size_t kept = 0;
  for (const auto count : seen.visible_count) kept += count > 0;
  return static_cast<double>(kept) / static_cast<double>(cloud.size());
}

TEST(RealLaserScan, ThreeDtkStationsAreInBeamOrderAndKeepTheirPoints) {
  for (const char* name : {"scan000.3d", "scan001.3d", "scan002.3d"}) {
    SCOPED_TRACE(name);
    const PointCloud cloud = read_cloud(repository_file(std::string("3dtk/") + name));
    ASSERT_EQ(cloud.stations.size(), 1u);
    const SurfelEstimate estimate = estimate_surfels(cloud, {});
    ASSERT_EQ(estimate.noise.stations.size(), 1u);
    const StationNoise& noise = estimate.noise.stations[0];
    EXPECT_TRUE(noise.beam_order);
    EXPECT_NEAR(noise.beam_step * 180.0 / M_PI, 0.5, 1e-3);
    EXPECT_TRUE(estimate.carving.implausible.empty());
    EXPECT_GT(estimate.carving.shrunk, 0u);
    EXPECT_GE(kept_from_its_station(cloud, estimate), 0.995);
  }
}

TEST(RealLaserScan, PclRoomScanFromItsOriginKeepsItsPoints) {
  // The file records no station (PCL's default VIEWPOINT): its scanner
  // stood at the origin, as a project with an identity pose says.
  PointCloud cloud = read_cloud(repository_file("pcl/room_scan1.pcd"));
  cloud.stations = {{"room_scan1", {}}};
  const SurfelEstimate estimate = estimate_surfels(cloud, {});
  const StationNoise& noise = estimate.noise.stations.at(0);
  EXPECT_TRUE(noise.beam_order);
  EXPECT_NEAR(noise.beam_step * 180.0 / M_PI, 0.972, 1e-3);
  // Ranges rounded to 1 cm: at 10 cm most returns share theirs with the
  // next, and the noise read there is the rounding's, not 0 (it was 0.0 mm).
  EXPECT_GE(noise.bins.at(0).sigma, 0.8 * 0.01 / std::sqrt(12.0));
  EXPECT_TRUE(estimate.carving.implausible.empty());
  EXPECT_GE(kept_from_its_station(cloud, estimate), 0.995);
}

TEST(RealLaserScan, AStationTurnedAmongTheOthersIsNotCarved) {
  // The three stations with their .pose files, registered: none is refused.
  const PointCloud scene = read_cloud(repository_file("3dtk/scans.project.json"));
  ASSERT_EQ(scene.stations.size(), 3u);
  EXPECT_TRUE(estimate_surfels(scene, {}).carving.implausible.empty());
  // The second turned a quarter about its station, with its points: still
  // in beam order (a pose moves a scan and its station together), but its
  // lines of sight now cross the other two scans' walls.
  PointCloud turned = scene;
  const Eigen::Vector3d origin = turned.stations[1].frame.origin;
  const Eigen::AngleAxisd quarter(M_PI / 2.0, Eigen::Vector3d::UnitZ());
  for (std::size_t i = 0; i < turned.size(); ++i) {
    if (turned.station_ids[i] != 1) continue;
    turned.positions[i] =
        (origin + quarter * (turned.positions[i].cast<double>() - origin)).cast<float>();
  }
  const SurfelEstimate estimate = estimate_surfels(turned, {});
  bool refused = false;
  for (const auto& station : estimate.carving.implausible) {
    if (station.name != turned.stations[1].name) continue;
    refused = true;
    EXPECT_TRUE(station.beam_order);
    EXPECT_GT(station.by_others_share, kMaxBlockedShare);
  }
  EXPECT_TRUE(refused);
}

}  // namespace
}  // namespace occlusion
