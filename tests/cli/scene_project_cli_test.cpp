// A project file through the command line (files/projects/mixed.project.json:
// E57, PCD, PLY and text scans with their poses): -fscan takes it as it takes
// any cloud, given directly or named by --config, and its full output holds
// the scene as the library reads it: the same points, stations and station
// of each point, the stations where the poses put them (worked by hand in
// files/projects/SOURCES.md and tests/io/scene_project_test.cpp).

#include <gtest/gtest.h>

#include <string>

#include "occlusion/io/cloud_io.hpp"
#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::CliRun;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kProject = kSource + "/files/projects/mixed.project.json";

void expect_the_scene(const PointCloud& written) {
  const PointCloud scene = read_cloud(kProject);
  ASSERT_EQ(written.size(), 16u);
  ASSERT_EQ(written.size(), scene.size());
  for (std::size_t i = 0; i < scene.size(); ++i) {
    EXPECT_EQ(written.original_position(i), scene.original_position(i)) << i;
  }
  EXPECT_EQ(written.station_ids, scene.station_ids);
  ASSERT_EQ(written.stations.size(), 4u);
  const Eigen::Vector3d by_hand[] = {{5, 4, 6}, {2, 0, 0}, {0, 7, 0.5}, {0, 3, 0}};
  for (std::size_t s = 0; s < 4; ++s) {
    EXPECT_EQ(written.stations[s].name, scene.stations[s].name);
    EXPECT_LT((written.to_original(written.stations[s].frame.origin) - by_hand[s]).norm(), 1e-9)
        << s;
  }
  for (std::size_t i = 0; i < 16; ++i) EXPECT_EQ(written.station_ids[i], static_cast<int>(i / 4));
}

TEST(SceneProjectCli, ScanTakesAProjectAsOneCloud) {
  TempDir dir;
  const CliRun run = run_cli("-fscan '" + kProject + "' -q --out '" + dir.path() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // Only the PLY scan has colours: the warning says they were dropped.
  EXPECT_NE(run.err.find("colours were dropped"), std::string::npos) << run.err;
  expect_the_scene(read_cloud(dir.file("mixed.project.scan_full.ply")));
}

TEST(SceneProjectCli, ConfigNamesAProject) {
  TempDir dir;
  dir.write("config.json", R"({"occlusion": {"scan": {"path": ")" + kProject + R"(", "out": ")" +
                               dir.path() + "\"}}}");
  const Json::Value report = run_json("-fscan --config '" + dir.file("config.json") + "'");
  EXPECT_EQ(report["input"].asString(), kProject);
  expect_the_scene(read_cloud(dir.file("mixed.project.scan_full.ply")));
}

TEST(SceneProjectCli, AScanThatCannotBePlacedIsABadInput) {
  TempDir dir;
  dir.write("plain.txt", "0 0 0\n1 0 0\n0 1 0\n");
  dir.write("p.project.json", R"({"scans": [{"path": "plain.txt"}]})");
  const CliRun run = run_cli("-fscan '" + dir.file("p.project.json") + "' -q");
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find("cannot be placed"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("\"pose\""), std::string::npos) << run.err;
}

}  // namespace
}  // namespace occlusion
