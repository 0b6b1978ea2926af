// -fscan's per-station answers through the command line, on a PLY that
// records two stations (a plate before a wall, the shadows worked out by hand:
// support/cloud_scenes.hpp): the report names each station as the file does,
// with the share it sees and the share only it sees, which add up with the
// shares seen by several and by none; the text says the same; SCENE.scan_full.ply
// holds each point's visible_count and first_station, as the hand-worked
// shadows say; and `--scans` leaves a station out of the viewpoints.

#include <gtest/gtest.h>

#include <string>

#include "occlusion/io/cloud_io.hpp"
#include "run_cli.hpp"
#include "support/cloud_scenes.hpp"

namespace occlusion {
namespace {

using Scene = testing::PlateBeforeWall;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSpheres = " --primitive sphere --point-radius 0.02";

// Scan B recorded the wall's half y > 0 and the patch behind the plate
// (80 x 100 + 25 points), scan A the rest.
constexpr std::uint64_t kPointsOfB = 80 * 100 + Scene::kBehindPoints;

std::string write_scene(const TempDir& dir) {
  PointCloud cloud = Scene::cloud();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const bool by_b = cloud.labels[i] == Scene::kBehind ||
                      (cloud.labels[i] == Scene::kWall && cloud.positions[i].y() > 0.0f);
    cloud.station_ids.push_back(by_b ? 1 : 0);
  }
  Station a{"Scan A", {}}, b{"Scan B", {}};
  a.frame.origin = Scene::a();
  b.frame.origin = Scene::b();
  cloud.stations = {a, b};
  const std::string path = dir.file("plate.ply");
  write_cloud(path, cloud);
  return path;
}

const ScalarField& field(const CloudReadReport& report, const std::string& name) {
  for (const auto& f : report.extra_fields) {
    if (f.name == name) return f;
  }
  throw std::runtime_error("no field " + name);
}

TEST(StationAnswersCli, EachStationsShareAndWhatOnlyItSeesAddUpAndAreWritten) {
  const TempDir dir;
  const std::string path = write_scene(dir);
  const Json::Value json =
      run_json("-fscan '" + path + "'" + kSpheres + " --out '" + dir.path() + "'");
  EXPECT_EQ(json["viewpoint_source"].asString(), "stations of the file");
  ASSERT_EQ(json["viewpoints"].size(), 2u);
  EXPECT_EQ(json["viewpoints"][0]["name"].asString(), "Scan A");
  EXPECT_EQ(json["viewpoints"][1]["name"].asString(), "Scan B");
  const double points = json["points"].asDouble();
  double only = 0.0;
  std::uint64_t only_points = 0;
  for (const auto& v : json["viewpoints"]) {
    // The CLI's JSON keeps 15 significant digits.
    EXPECT_NEAR(v["only_fraction"].asDouble(), v["only_points"].asDouble() / points, 1e-14);
    EXPECT_NEAR(v["visible_fraction"].asDouble(), v["visible_points"].asDouble() / points, 1e-14);
    // A shadow on the wall: 40 x 40 cells give or take the band; only the other station sees it.
    EXPECT_GE(v["only_points"].asUInt64(), 34u * 34u);
    EXPECT_LE(v["only_points"].asUInt64(), 46u * 46u);
    only += v["only_fraction"].asDouble();
    only_points += v["only_points"].asUInt64();
  }
  EXPECT_EQ(json["seen_by_none_points"].asUInt64(), Scene::kBehindPoints);
  EXPECT_EQ(only_points + json["seen_by_several_points"].asUInt64() +
                json["seen_by_none_points"].asUInt64(),
            json["points"].asUInt64());
  EXPECT_NEAR(
      only + json["seen_by_several_fraction"].asDouble() + json["seen_by_none_fraction"].asDouble(),
      1.0, 1e-12);

  // The full cloud's fields: how many stations see each point and the first.
  CloudReadReport report;
  const PointCloud full = read_cloud(dir.file("plate.scan_full.ply"), {}, &report);
  const ScalarField& count = field(report, "visible_count");
  const ScalarField& first = field(report, "first_station");
  ASSERT_EQ(first.values.size(), full.size());
  EXPECT_TRUE(first.integer);
  const PointCloud scene = Scene::cloud();
  std::size_t decided = 0;
  std::uint64_t first_a = 0;
  for (std::size_t i = 0; i < full.size(); ++i) {
    first_a += first.values[i] == 1.0f;
    const Scene::Seen truth = Scene::expected(full.positions[i], scene.labels[i], 3 * Scene::kStep);
    if (truth.count < 0) continue;
    ++decided;
    EXPECT_EQ(count.values[i], truth.count) << full.positions[i].transpose();
    EXPECT_EQ(first.values[i], truth.first) << full.positions[i].transpose();
  }
  EXPECT_GT(decided, full.size() * 8 / 10);
  // Station A is first for all it sees: the points only it sees and those seen by both.
  EXPECT_EQ(first_a, json["viewpoints"][0]["only_points"].asUInt64() +
                         json["seen_by_several_points"].asUInt64());

  // The text gives the same figures.
  const auto text = run_cli("-fscan '" + path + "'" + kSpheres);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("Scan B"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("only it " + json["viewpoints"][1]["only_points"].asString()),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("seen by several"), std::string::npos) << text.out;
}

TEST(StationAnswersCli, ScansLeavesAStationOut) {
  const TempDir dir;
  const std::string path = write_scene(dir);
  const Json::Value json = run_json("-fscan '" + path + "'" + kSpheres + " --scans 'Scan B'");
  // B's points are left, and B is the one viewpoint, by its name; with the
  // plate (A's) gone nothing hides the patch, and B alone sees everything.
  EXPECT_EQ(json["points"].asUInt64(), kPointsOfB);
  EXPECT_EQ(json["station_filter"]["dropped_other_scans"].asUInt64(),
            Scene::cloud().size() - kPointsOfB);
  ASSERT_EQ(json["viewpoints"].size(), 1u);
  EXPECT_EQ(json["viewpoints"][0]["name"].asString(), "Scan B");
  EXPECT_EQ(json["viewpoints"][0]["only_points"].asUInt64(), kPointsOfB);
  EXPECT_EQ(json["seen_by_several_points"].asUInt64(), 0u);
  EXPECT_EQ(json["seen_by_none_points"].asUInt64(), 0u);
}

}  // namespace
}  // namespace occlusion
