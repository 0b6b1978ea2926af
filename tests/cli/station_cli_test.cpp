// A PLY that records its scanner stations, through the command line: the
// stations are the viewpoints, `--scans` picks them, `--min-range` and
// `--max-range` drop points by their range, and -fscan's outputs keep the
// stations, each point's station and its intensity.

#include <gtest/gtest.h>

#include <string>

#include "occlusion/io/cloud_io.hpp"
#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::run_cli;
using testing::run_json;
using testing::TempDir;

// A floor seen by "west" and a wall x = 4 seen by "east" (outside the box
// of the points), every point with an intensity.
PointCloud two_station_room() {
  PointCloud cloud;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      cloud.positions.emplace_back(0.1f * i, 0.1f * j, 0.0f);
      cloud.station_ids.push_back(0);
      cloud.positions.emplace_back(4.0f, 0.1f * i, 0.075f * j);
      cloud.station_ids.push_back(1);
    }
  }
  for (std::size_t k = 0; k < cloud.size(); ++k) cloud.intensities.push_back(0.5f * (k % 7));
  Station west{"west", {}}, east{"east", {}};
  west.frame.origin = Eigen::Vector3d(1.5, 2.0, 1.5);
  east.frame.origin = Eigen::Vector3d(6.0, 2.0, 1.5);
  cloud.stations = {west, east};
  return cloud;
}

const std::string kSpheres = " --primitive sphere --point-radius 0.05";

TEST(StationCli, StationsAreTheViewpointsAndTheOutputsKeepThem) {
  const TempDir dir;
  const std::string path = dir.file("room.ply");
  write_cloud(path, two_station_room());
  const Json::Value json =
      run_json("-fscan '" + path + "'" + kSpheres + " --out '" + dir.path() + "'");
  EXPECT_EQ(json["viewpoint_source"].asString(), "stations of the file");
  ASSERT_EQ(json["viewpoints"].size(), 2u);
  EXPECT_EQ(json["viewpoints"][1]["name"].asString(), "east");
  EXPECT_EQ(json["viewpoints"][1]["position"][0].asDouble(), 6.0);
  // "east" stands outside the box of the points, as scanners do: no warning.
  for (const auto& warning : json["warnings"]) {
    EXPECT_EQ(warning.asString().find("outside the occupied space"), std::string::npos) << warning;
  }
  const PointCloud seen = read_cloud(dir.file("room.scan.ply"));
  ASSERT_EQ(seen.stations.size(), 2u);
  EXPECT_EQ(seen.stations[1].name, "east");
  EXPECT_EQ(seen.stations[1].frame.origin, Eigen::Vector3d(6.0, 2.0, 1.5));
  EXPECT_EQ(seen.station_ids.size(), seen.size());
  EXPECT_EQ(seen.intensities.size(), seen.size());

  // A pattern given on the command line wins.
  const Json::Value pattern = run_json("-fscan '" + path + "'" + kSpheres + " --pattern 1");
  EXPECT_EQ(pattern["viewpoint_source"].asString(), "pattern 1");
  EXPECT_EQ(pattern["parameters"]["pattern"].asInt(), 1);
}

TEST(StationCli, ScansAndRangesDropPointsAndSaySo) {
  const TempDir dir;
  const std::string path = dir.file("room.ply");
  write_cloud(path, two_station_room());
  // The wall alone, less its points within 2.2 m of "east" at (6, 2, 1.5):
  // those at distance <= 2.2, i.e. (y - 2)^2 + (z - 1.5)^2 <= 0.84.
  const Json::Value json =
      run_json("-fscan '" + path + "'" + kSpheres + " --scans east --max-range 2.2");
  std::size_t near = 0;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      const double dy = 0.1f * i - 2.0, dz = 0.075f * j - 1.5;
      near += 4.0 + dy * dy + dz * dz <= 2.2 * 2.2 ? 1 : 0;
    }
  }
  EXPECT_EQ(json["points"].asUInt64(), near);
  EXPECT_EQ(json["station_filter"]["dropped_other_scans"].asUInt64(), 41u * 41u);
  EXPECT_EQ(json["station_filter"]["dropped_too_far"].asUInt64(), 41u * 41u - near);
  EXPECT_EQ(json["viewpoints"].size(), 1u);
  EXPECT_EQ(json["viewpoints"][0]["name"].asString(), "east");
}

TEST(StationCli, ScansAndRangesRefuseWhatTheFileCannotAnswer) {
  const TempDir dir;
  const std::string path = dir.file("room.ply");
  write_cloud(path, two_station_room());
  const auto unknown = run_cli("-fscan '" + path + "' --scans north -q");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--scans names no station of"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("(its stations: 'west', 'east')"), std::string::npos) << unknown.err;

  PointCloud plain;
  plain.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::string plain_path = dir.file("plain.ply");
  write_cloud(plain_path, plain);
  const auto no_station = run_cli("-poc '" + plain_path + "' --min-range 0.5 -q");
  EXPECT_EQ(no_station.exit_code, 2);
  EXPECT_NE(no_station.err.find("--min-range measures each point's range from its own station"),
            std::string::npos)
      << no_station.err;
  const auto no_scans = run_cli("-fscan '" + plain_path + "' --scans west -q");
  EXPECT_EQ(no_scans.exit_code, 2);
  EXPECT_NE(no_scans.err.find("records no stations"), std::string::npos) << no_scans.err;
  const auto inverted = run_cli("-fscan '" + path + "' --min-range 3 --max-range 2 -q");
  EXPECT_EQ(inverted.exit_code, 2);
  EXPECT_NE(inverted.err.find("--max-range must be above min_range"), std::string::npos)
      << inverted.err;
}

}  // namespace
}  // namespace occlusion
