// Project files: several scans placed by their poses as one cloud, checked
// against poses worked by hand (files/projects/SOURCES.md, files/3dtk/).

#include "occlusion/io/scene_project.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

const std::string kFiles = std::string(OCCLUSION_SOURCE_DIR) + "/files/";

Eigen::Vector3d station_position(const PointCloud& cloud, std::size_t station) {
  return cloud.to_original(cloud.stations.at(station).frame.origin);
}

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_LT((actual - expected).norm(), tolerance)
      << actual.transpose() << " vs " << expected.transpose();
}

// The acceptance case: 3DTK's three stations with their .pose files, one
// scene, each station at its pose's position. By hand from the pose files
// (cm, left-handed, y up -> m, x = z, y = -x, z = y):
//   scan000.pose  0 0 0                      -> (0, 0, 0)
//   scan001.pose  -3.10605 -7.50803 156.917  -> (1.56917, 0.0310605, -0.0750803)
//   scan002.pose  -7.99848 -15.3529 337.973  -> (3.37973, 0.0799848, -0.153529)
TEST(SceneProject, ThreeDtkStationsLoadAsOneScene) {
  CloudReadReport report;
  const PointCloud scene = read_cloud(kFiles + "3dtk/scans.project.json", {}, &report);
  ASSERT_EQ(scene.size(), 3u * 81360u);
  ASSERT_EQ(scene.stations.size(), 3u);
  const Eigen::Vector3d expected[] = {
      {0, 0, 0}, {1.56917, 0.0310605, -0.0750803}, {3.37973, 0.0799848, -0.153529}};
  for (std::size_t s = 0; s < 3; ++s) {
    EXPECT_EQ(scene.stations[s].name, "scan00" + std::to_string(s));
    expect_near(station_position(scene, s), expected[s], 1e-6);
  }
  ASSERT_EQ(scene.station_ids.size(), scene.size());
  EXPECT_EQ(scene.station_ids[0], 0);
  EXPECT_EQ(scene.station_ids[81359], 0);
  EXPECT_EQ(scene.station_ids[81360], 1);
  EXPECT_EQ(scene.station_ids.back(), 2);
  // Each scan's points as the scan alone reads them (its own .pose applied).
  const PointCloud third = read_cloud(kFiles + "3dtk/scan002.3d");
  expect_near(scene.original_position(2 * 81360 + 17), third.original_position(17), 1e-6);
  EXPECT_TRUE(report.warnings.empty());
}

// files/projects/mixed.project.json, worked by hand.
TEST(SceneProject, ScansOfDifferentFormatsWithTheirPoses) {
  CloudReadReport report;
  const PointCloud scene = read_cloud(kFiles + "projects/mixed.project.json", {}, &report);
  ASSERT_EQ(scene.size(), 16u);
  ASSERT_EQ(scene.stations.size(), 4u);

  // E57: its station at (4, 5, 6), turned a quarter about z (x -> y) and
  // moved (10, 0, 0): (-5, 4, 6) + (10, 0, 0).
  const PointCloud e57 = read_cloud(kFiles + "e57/translationWithoutRotation.e57");
  ASSERT_EQ(e57.stations.size(), 1u);
  EXPECT_EQ(scene.stations[0].name, e57.stations[0].name);
  expect_near(station_position(scene, 0), {5, 4, 6}, 1e-12);
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector3d p = e57.original_position(i);
    expect_near(scene.original_position(i), Eigen::Vector3d(10 - p.y(), p.x(), p.z()), 1e-6);
  }
  // PCD: no station of its own, so one at the TUM pose's origin (2, 0, 0).
  EXPECT_EQ(scene.stations[1].name, "pcd");
  expect_near(station_position(scene, 1), {2, 0, 0}, 1e-12);
  expect_near(scene.original_position(4 + 3), {3, 0.5, 0.5}, 1e-7);
  // PLY: turned a half about z, moved (0, 7, 0.5); (2, 0.5, 0) -> (-2, 6.5, 0.5).
  EXPECT_EQ(scene.stations[2].name, "wall");
  expect_near(station_position(scene, 2), {0, 7, 0.5}, 1e-12);
  expect_near(scene.original_position(8 + 1), {-2, 6.5, 0.5}, 1e-7);
  // Text in millimetres moved (0, 3, 0): (1000, 500, 500) mm -> (1, 3.5, 0.5) m.
  EXPECT_EQ(scene.stations[3].name, "text");
  expect_near(station_position(scene, 3), {0, 3, 0}, 1e-12);
  expect_near(scene.original_position(12 + 3), {1, 3.5, 0.5}, 1e-7);

  ASSERT_EQ(scene.station_ids.size(), 16u);
  for (std::size_t i = 0; i < 16; ++i) EXPECT_EQ(scene.station_ids[i], static_cast<int>(i / 4));
  // Only the PLY has colours: dropped, and said so.
  EXPECT_FALSE(scene.has_colours());
  bool warned = false;
  for (const std::string& warning : report.warnings) {
    warned |= warning.find("colours were dropped: 3 of 4 scans have none") != std::string::npos;
  }
  EXPECT_TRUE(warned) << ::testing::PrintToString(report.warnings);
  scene.validate();
}

TEST(SceneProject, AttributesEveryScanHasAreKept) {
  testing::ScratchDirectory dir;
  PointCloud a = testing::labelled_cloud();
  a.positions = {{1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  write_cloud(dir.file("a.ply"), a);
  write_cloud(dir.file("b.pcd"), a);
  testing::write_text(
      dir.file("s.project.json"),
      R"({"scans": [{"path": "a.ply", "pose": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]},
                        {"path": "b.pcd", "pose": [[1,0,0,0],[0,1,0,5],[0,0,1,0],[0,0,0,1]]}]})");
  CloudReadReport report;
  const PointCloud scene = read_cloud(dir.file("s.project.json"), {}, &report);
  ASSERT_EQ(scene.size(), 8u);
  ASSERT_EQ(scene.colours.size(), 8u);
  EXPECT_EQ(scene.colours[5], a.colours[1]);
  ASSERT_EQ(scene.labels.size(), 8u);
  EXPECT_EQ(scene.labels[6], a.labels[2]);
  EXPECT_EQ(scene.class_names, a.class_names);
  // Instances 5, -1, 0, 70000 twice: the second scan's are moved past the first's.
  ASSERT_EQ(scene.instances.size(), 8u);
  EXPECT_EQ(scene.instances[0], 5);
  EXPECT_EQ(scene.instances[5], -1);
  EXPECT_EQ(scene.instances[4], 70006);
  EXPECT_EQ(scene.instances[6], 70001);
  EXPECT_TRUE(report.warnings.empty()) << ::testing::PrintToString(report.warnings);
}

// A scan in UTM coordinates: the scene's shift keeps float's precision.
TEST(SceneProject, FarPosesKeepTheirPrecision) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("near.txt"), "0.001 0.002 0.003\n1 1 1\n");
  testing::write_text(dir.file("far.project.json"),
                      R"({"scans": [{"path": "near.txt",
                          "pose": [[1,0,0,500000.25],[0,1,0,5400000.5],[0,0,1,100],[0,0,0,1]]}]})");
  const PointCloud scene = read_cloud(dir.file("far.project.json"));
  EXPECT_TRUE(scene.shifted());
  expect_near(scene.original_position(0), {500000.251, 5400000.502, 100.003}, 1e-6);
  expect_near(station_position(scene, 0), {500000.25, 5400000.5, 100}, 1e-9);
}

// max_points bounds the scene, not each scan: two scans of 2 points hold 4.
TEST(SceneProject, MaxPointsCountsTheWholeScene) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("two.txt"), "1 2 3\n4 5 6\n");
  testing::write_text(dir.file("s.project.json"),
                      R"({"scans": [
                        {"path": "two.txt", "station": "a", "pose": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]},
                        {"path": "two.txt", "station": "b", "pose": [[1,0,0,1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]})");
  CloudReadOptions options;
  for (const std::size_t limit : {1u, 2u, 3u}) {
    options.max_points = limit;
    EXPECT_THROW(read_cloud(dir.file("s.project.json"), options), TooManyPoints) << limit;
  }
  options.max_points = 4;
  EXPECT_EQ(read_cloud(dir.file("s.project.json"), options).size(), 4u);
}

TEST(SceneProject, AScanThatCannotBePlacedIsRefused) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("plain.txt"), "1 2 3\n");
  testing::write_text(dir.file("p.project.json"), R"({"scans": [{"path": "plain.txt"}]})");
  testing::expect_input_error([&] { read_cloud(dir.file("p.project.json")); }, "plain.txt", 0,
                              "cannot be placed");
}

TEST(SceneProject, MalformedProjectsNameTheLine) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("a.txt"), "1 2 3\n");
  const std::string path = dir.file("bad.project.json");
  const auto expect = [&](const std::string& text, std::size_t line, const std::string& message) {
    testing::write_text(path, text);
    testing::expect_input_error([&] { read_cloud(path); }, "bad.project.json", line, message);
  };
  expect(R"({"scans": []})", 1, "non-empty list");
  expect("{\"scans\": [\n{\"path\": \"a.txt\", \"colour\": 1}]}", 2, "unknown field 'colour'");
  expect("{\"scans\": [\n{\"path\": \"a.txt\",\n \"pose\": [1, 2, 3, 0, 0, 0, 1]}]}", 3,
         "no 'pose_format'");
  expect(
      "{\"scans\": [{\"path\": \"a.txt\", \"pose_format\": \"tum\",\n"
      " \"pose\": [1, 2, 3, 0, 0, 0, 2]}]}",
      2, "length");
  expect(
      "{\"scans\": [{\"path\": \"a.txt\", \"pose\": [[2,0,0,0],[0,2,0,0],[0,0,2,0],[0,0,0,1]]}]}",
      1, "not a rotation");
  expect(R"({"scans": [{"path": "a.txt", "pose_format": "euler", "pose_file": "x"}]})", 1,
         "unknown pose format");
  expect(R"({"scans": [{"path": "a.txt", "units": "inch"}]})", 1, "m, cm or mm");
  expect(R"({"scans": [{"path": "other.project.json"}]})", 1, "cannot be a project");
  expect(R"({"scans": [{"path": "a.txt", "layout": "uosr"}]})", 1, "no .3d file");
  expect(R"({"scans": [{"path": "a.txt"}], "scans": []})", 0, "not a valid project file");
  // Two scans of one name.
  expect(R"({"scans": [{"path": "a.txt", "pose": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]},
                       {"path": "a.txt", "pose": [[1,0,0,1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]})",
         2, "two stations are named 'a'");
}

TEST(SceneProject, ThreeDtkLayoutAndPoseFile) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("scan000.3d"), "0 0 100 7.5\n100 0 0 2\n");
  testing::write_text(dir.file("scan000.pose"), "0 0 200\n0 90 0\n");
  testing::write_text(dir.file("r.project.json"),
                      R"({"scans": [{"path": "scan000.3d", "layout": "uosr"}]})");
  const PointCloud scene = read_cloud(dir.file("r.project.json"));
  ASSERT_EQ(scene.size(), 2u);
  ASSERT_EQ(scene.intensities.size(), 2u);
  EXPECT_EQ(scene.intensities[0], 7.5f);
  // ThreeDtkRotationWorkedByHand (pose_file_test.cpp): (100, 0, 0) cm -> (1, 0, 0) m.
  expect_near(scene.original_position(1), {1, 0, 0}, 1e-6);
  expect_near(station_position(scene, 0), {2, 0, 0}, 1e-12);
}

// A project written back (as a registration writes refined poses) reads as
// the same scans, each pose in the format and place the user gave it.
TEST(SceneProject, WrittenBackItReadsTheSame) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("a.txt"), "1 2 3\n");
  testing::write_text(dir.file("scan001.3d"), "0 0 100 7.5\n");
  testing::write_text(dir.file("b.pose"), "1 2 3\n10 20 30\n");
  testing::write_text(dir.file("in.project.json"),
                      R"({"scans": [
        {"path": "a.txt", "pose": [[0,-1,0,1.5],[1,0,0,0],[0,0,1,0],[0,0,0,1]], "station": "A"},
        {"path": "a.txt", "pose": [7, 1, 2, 3, 0, 0, 0.6, 0.8], "pose_format": "tum",
         "units": "mm", "station": "B"},
        {"path": "a.txt", "pose_file": "b.pose", "station": "C"},
        {"path": "scan001.3d", "layout": "uosr"}]})");
  const std::vector<SceneScan> scans = read_project_file(dir.file("in.project.json"));
  write_project_file(dir.file("out.project.json"), scans);
  const std::vector<SceneScan> back = read_project_file(dir.file("out.project.json"));
  ASSERT_EQ(back.size(), scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(back[i].path, scans[i].path);
    EXPECT_EQ(back[i].named_path, scans[i].named_path);
    EXPECT_EQ(back[i].pose_path, scans[i].pose_path);
    EXPECT_EQ(back[i].station, scans[i].station);
    EXPECT_EQ(back[i].layout, scans[i].layout);
    EXPECT_EQ(back[i].metres_per_unit, scans[i].metres_per_unit);
    ASSERT_EQ(back[i].pose.has_value(), scans[i].pose.has_value());
    if (!scans[i].pose) continue;
    EXPECT_EQ(back[i].pose->format, scans[i].pose->format);
    EXPECT_EQ(back[i].pose->timestamp, scans[i].pose->timestamp);
    EXPECT_LT((back[i].pose->scan_to_scene.matrix() - scans[i].pose->scan_to_scene.matrix())
                  .cwiseAbs()
                  .maxCoeff(),
              1e-14);
  }
  EXPECT_EQ(scans[1].pose->timestamp, 7.0);
  const PointCloud before = read_cloud(dir.file("in.project.json"));
  const PointCloud after = read_cloud(dir.file("out.project.json"));
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(after.original_position(i), before.original_position(i));
  }
}

}  // namespace
}  // namespace occlusion
