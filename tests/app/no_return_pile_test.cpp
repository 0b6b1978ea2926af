// No-return piles (app/no_return_pile): 3DTK's SICK scans write a beam that met
// nothing as a point at 32.77 m, 1.6-2 % of each station's points. They are
// found on each station, the value the warning names drops exactly them, and
// scans without one say nothing: a room, a far wall seen square, a scanner at
// the centre of a spherical tank, PCL's room scan.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "occlusion/app/in_memory_jobs.hpp"
#include "occlusion/app/no_return_pile.hpp"
#include "occlusion/app/station_filter.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/core/sampling.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

std::string repository_file(const std::string& path) {
  return std::string(OCCLUSION_SOURCE_DIR) + "/files/" + path;
}

Eigen::Vector3f random_direction(Rng& rng) {
  const double r1 = rng.uniform();
  return sample_sphere_direction(r1, rng.uniform()).cast<float>();
}

// A closed 8 x 6 x 3 m room seen from a station at (4, 3, 1.5): each point
// where a random direction from the station meets a wall, floor or ceiling.
PointCloud room_scan(std::size_t points, std::uint64_t seed) {
  Rng random(seed);
  const Eigen::Vector3f station(4.0f, 3.0f, 1.5f);
  const Eigen::Vector3f lo(0, 0, 0), hi(8, 6, 3);
  PointCloud cloud;
  for (std::size_t i = 0; i < points; ++i) {
    const Eigen::Vector3f d = random_direction(random);
    float t = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (d[a] != 0.0f) t = std::min(t, ((d[a] > 0 ? hi[a] : lo[a]) - station[a]) / d[a]);
    }
    cloud.positions.push_back(station + t * d);
  }
  Station s;
  s.name = "room";
  s.frame.origin = station.cast<double>();
  cloud.stations.push_back(s);
  return cloud;
}

// `cloud` with `count` more points at `range` from its station in random directions.
void add_no_returns(PointCloud& cloud, std::size_t count, float range, std::uint64_t seed) {
  Rng random(seed);
  const Eigen::Vector3f station = cloud.stations.at(0).frame.origin.cast<float>();
  for (std::size_t i = 0; i < count; ++i) {
    cloud.positions.push_back(station + range * random_direction(random));
  }
}

TEST(NoReturnPile, EachThreeDtkStationHasOneAndItsValueDropsExactlyIt) {
  const PointCloud scene = read_cloud(repository_file("3dtk/scans.project.json"));
  ASSERT_EQ(scene.stations.size(), 3u);
  const std::vector<NoReturnPile> piles = find_no_return_piles(scene);
  ASSERT_EQ(piles.size(), 3u);
  std::size_t pile_points = 0;
  for (std::size_t s = 0; s < 3; ++s) {
    SCOPED_TRACE(piles[s].station);
    EXPECT_EQ(piles[s].station, scene.stations[s].name);
    EXPECT_NEAR(piles[s].range, 32.767, 0.005);
    const double share =
        static_cast<double>(piles[s].points) / static_cast<double>(piles[s].station_points);
    EXPECT_GT(share, 0.015);
    EXPECT_LT(share, 0.021);
    pile_points += piles[s].points;
  }
  // The warning names a value that drops the piles and nothing else.
  std::vector<std::string> warnings;
  warn_no_return_piles(scene, 0.0, warnings);
  ASSERT_EQ(warnings.size(), 3u);
  const double below = max_range_below(piles[0]);
  EXPECT_NE(warnings[0].find("--max-range " + std::to_string(below).substr(0, 5)),
            std::string::npos)
      << warnings[0];
  PointCloud filtered = scene;
  StationFilter filter;
  filter.max_range = below;
  const StationFilterReport dropped = apply_station_filter(filtered, filter, "3dtk");
  EXPECT_EQ(dropped.too_far, pile_points);
  EXPECT_TRUE(find_no_return_piles(filtered).empty());
  // With max_range on, the user has decided: no warning.
  warnings.clear();
  warn_no_return_piles(scene, 40.0, warnings);
  EXPECT_TRUE(warnings.empty());
}

TEST(NoReturnPile, ARoomScanWithOneIsFoundAndItsCountIsExact) {
  PointCloud cloud = room_scan(50'000, 1);
  EXPECT_TRUE(find_no_return_piles(cloud).empty());
  add_no_returns(cloud, 1'000, 32.77f, 2);
  const std::vector<NoReturnPile> piles = find_no_return_piles(cloud);
  ASSERT_EQ(piles.size(), 1u);
  EXPECT_EQ(piles[0].points, 1'000u);
  EXPECT_EQ(piles[0].station_points, 51'000u);
  EXPECT_NEAR(piles[0].range, 32.77, 1e-4);
  EXPECT_LT(max_range_below(piles[0]), 32.77 * (1.0 - kNoReturnShell));
  EXPECT_GT(max_range_below(piles[0]), 32.7);
  // Too few to be a pile: 0.2 % of the points.
  PointCloud few = room_scan(50'000, 1);
  add_no_returns(few, 100, 32.77f, 2);
  EXPECT_TRUE(find_no_return_piles(few).empty());
}

TEST(NoReturnPile, SurfacesAtTheFarthestRangeAreNone) {
  // A wall 30 m away seen square: its nearest point is at 30 m, its farthest
  // (the corners) fall off continuously.
  PointCloud wall;
  for (int i = -100; i <= 100; ++i) {
    for (int j = -100; j <= 100; ++j) wall.positions.emplace_back(30.0f, 0.05f * i, 0.05f * j);
  }
  wall.stations.push_back({"wall", {}});
  EXPECT_TRUE(find_no_return_piles(wall).empty());
  // A scanner at the centre of a spherical tank: one range everywhere.
  PointCloud tank;
  tank.stations.push_back({"tank", {}});
  add_no_returns(tank, 20'000, 5.0f, 3);
  EXPECT_TRUE(find_no_return_piles(tank).empty());
  // PCL's room scan, from its origin.
  PointCloud room = read_cloud(repository_file("pcl/room_scan1.pcd"));
  room.stations = {{"room_scan1", {}}};
  EXPECT_TRUE(find_no_return_piles(room).empty());
}

TEST(NoReturnPile, TheJobsWarnWhateverTheDoor) {
  PointCloud cloud = room_scan(20'000, 4);
  add_no_returns(cloud, 400, 32.77f, 5);
  ScanRequest request;
  request.path = "room";
  const ScanReport scan = scan_in_memory(cloud, request);
  const auto mentions = [](const std::vector<std::string>& warnings) {
    std::size_t n = 0;
    for (const auto& w : warnings) n += w.find("no-return") != std::string::npos;
    return n;
  };
  EXPECT_EQ(mentions(scan.warnings), 1u);
  CloudOcclusionRequest poc;
  poc.path = "room";
  poc.num_rays_per_vp = 1000;
  EXPECT_EQ(mentions(cloud_occlusion_in_memory(cloud, poc).warnings), 1u);
  // Dropped as the warning says: the job keeps the room, and says nothing.
  request.max_range = max_range_below(find_no_return_piles(cloud).at(0));
  const ScanReport kept = scan_in_memory(cloud, request);
  EXPECT_EQ(mentions(kept.warnings), 0u);
  EXPECT_EQ(kept.station_filter.too_far, 400u);
}

}  // namespace
}  // namespace occlusion
