// A ScanNet scene goes straight into -fscan, -poc and the study: no class
// comments, no mapping file.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/study_job.hpp"
#include "support/scannet_scene.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;

// A closed 3 x 3 x 2.4 m room sampled every 10 cm, as a ScanNet mesh's
// vertices: floor (NYU40 2), ceiling (22), walls (1).
fs::path write_room(const fs::path& dir) {
  testing::ScanNetScene scene;
  const auto add = [&](float x, float y, float z, std::uint16_t label) {
    scene.positions.emplace_back(x, y, z);
    scene.colours.push_back({static_cast<std::uint8_t>(label * 9), 128, 64});
    scene.labels.push_back(label);
  };
  const int n = 30, h = 24;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      add(0.1f * i, 0.1f * j, 0.0f, 2);
      add(0.1f * i, 0.1f * j, 2.4f, 22);
    }
  }
  for (int k = 1; k < h; ++k) {
    for (int i = 0; i < n; ++i) {
      add(0.1f * i, 0.0f, 0.1f * k, 1);
      add(3.0f, 0.1f * i, 0.1f * k, 1);
      add(3.0f - 0.1f * i, 3.0f, 0.1f * k, 1);
      add(0.0f, 3.0f - 0.1f * i, 0.1f * k, 1);
    }
  }
  scene.faces = {{0, 1, 2}};
  return testing::write_scannet_scene(dir, "scene0042_00", scene);
}

TEST(ScanNetJobs, ScanAndCloudOcclusionNameTheNyu40Classes) {
  testing::ScratchDirectory dir;
  const fs::path room = write_room(dir.path());

  ScanRequest scan;
  scan.path = room.string();
  scan.viewpoints = ViewpointChoice::from_points({Eigen::Vector3d(1.5, 1.5, 1.2)});
  scan.threads = 2;
  const ScanReport seen = run_scan(scan);
  EXPECT_GE(seen.result.visible_fraction, 0.99);
  std::vector<std::string> used;
  for (const ClassVisibility& c : seen.classes) {
    if (c.points > 0) used.push_back(c.name);
  }
  EXPECT_EQ(used, (std::vector<std::string>{"wall", "floor", "ceiling"}));

  CloudOcclusionRequest occlusion;
  occlusion.path = room.string();
  occlusion.viewpoints = ViewpointChoice::from_points({Eigen::Vector3d(1.5, 1.5, 1.2)});
  occlusion.num_rays_per_vp = 2000;
  occlusion.exterior = true;  // walls, floor and ceiling: NYU40 names them so too
  occlusion.threads = 2;
  const CloudOcclusionReport closed = run_cloud_occlusion(occlusion);
  EXPECT_LE(closed.result.occlusion_level, 0.02);
  ASSERT_TRUE(closed.exterior.has_value());
  EXPECT_EQ(closed.exterior->exterior_points, seen.result.visible_count.size());
}

TEST(ScanNetJobs, TheStudyScoresAScanNetSceneWithScannet20) {
  testing::ScratchDirectory dir;
  StudyRequest request;
  request.scenes = {write_room(dir.path()).string()};
  request.configurations = {
      {"centre", ViewpointChoice::from_points({Eigen::Vector3d(1.5, 1.5, 1.2)})}};
  request.class_mapping = "scannet20";
  request.tracing.num_rays_per_vp = 400;
  request.tracing.threads = 2;
  request.out = dir.file("study");
  const StudyReport report = run_study(request);
  ASSERT_EQ(report.table.rows.size(), 1u);
  EXPECT_EQ(report.runs_failed, 0u);
  // Scored over the 20 benchmark classes: the baseline finds most of the
  // floor and the walls (it gives the edges between them to one side), and
  // the ceiling is not scored.
  const auto cell = [&](const std::string& column) {
    return report.table.rows[0].at(report.table.column(column));
  };
  std::size_t scored = 0;
  for (const std::string& column : report.table.columns) scored += column.rfind("iou_", 0) == 0;
  EXPECT_EQ(scored, 20u);
  EXPECT_EQ(cell("status"), "ok");
  EXPECT_GT(std::stod(cell("iou_floor")), 0.8);
  EXPECT_GT(std::stod(cell("iou_wall")), 0.8);
  EXPECT_EQ(cell("iou_bed"), "");  // no ground truth, no prediction
  EXPECT_EQ(report.table.column("iou_ceiling"), report.table.columns.size());
}

}  // namespace
}  // namespace occlusion
