#include "occlusion/analysis/baseline_segmenter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "support/cloud_scenes.hpp"

namespace occlusion {
namespace {

using testing::add_grid;

enum Truth : std::int32_t { kFloor, kCeiling, kWall, kTable, kCabinet };

// The room [0, 4] x [0, 3] x [0, 2.5] sampled every 10 cm, without the
// points on its edges (which would belong to two surfaces at once), with a
// table top at 0.75 m and the side of a cabinet: a horizontal plane in mid-air
// and a vertical one too small for a wall.
PointCloud box_room() {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  const double step = 0.1;
  const int nx = 40, ny = 30, nz = 25;
  const auto inside = [](int na, int nb) {
    return [na, nb](int i, int j) { return i > 0 && i < na && j > 0 && j < nb; };
  };
  PointCloud cloud;
  add_grid(cloud, Eigen::Vector3d::Zero(), x, y, nx, ny, step, kFloor, inside(nx, ny));
  add_grid(cloud, nz * step * z, x, y, nx, ny, step, kCeiling, inside(nx, ny));
  add_grid(cloud, Eigen::Vector3d::Zero(), x, z, nx, nz, step, kWall, inside(nx, nz));
  add_grid(cloud, ny * step * y, x, z, nx, nz, step, kWall, inside(nx, nz));
  add_grid(cloud, Eigen::Vector3d::Zero(), y, z, ny, nz, step, kWall, inside(ny, nz));
  add_grid(cloud, nx * step * x, y, z, ny, nz, step, kWall, inside(ny, nz));
  add_grid(cloud, {1.5, 1.0, 0.75}, x, y, 20, 12, 0.05, kTable);
  add_grid(cloud, {3.0, 0.5, 0.1}, y, z, 10, 16, 0.05, kCabinet);
  return cloud;
}

MeshEstimate estimate(const PointCloud& cloud) {
  RegionGrowingOptions options;
  options.min_cluster_size = 50;
  options.max_cluster_size = 1000000;
  return estimate_mesh(cloud, options);
}

// Distinct ids, so that floor and ceiling can be told apart here.
BaselineOptions distinct_ids() {
  BaselineOptions options;
  options.floor_id = 10;
  options.ceiling_id = 11;
  options.wall_id = 12;
  options.clutter_id = 13;
  return options;
}

double share_labelled(const PointCloud& cloud, const std::vector<std::int32_t>& labels,
                      std::int32_t truth, std::int32_t expected) {
  std::size_t points = 0, right = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.labels[i] != truth) continue;
    ++points;
    right += labels[i] == expected ? 1 : 0;
  }
  return static_cast<double>(right) / static_cast<double>(points);
}

TEST(BaselineSegmenter, LabelsFloorCeilingWallsAndClutterOfABoxRoom) {
  const PointCloud cloud = box_room();
  const MeshEstimate mesh = estimate(cloud);
  const BaselineSegmentation result = segment_baseline(cloud, mesh, distinct_ids());
  ASSERT_EQ(result.labels.size(), cloud.size());

  EXPECT_GE(share_labelled(cloud, result.labels, kFloor, 10), 0.98);
  EXPECT_GE(share_labelled(cloud, result.labels, kCeiling, 11), 0.98);
  EXPECT_GE(share_labelled(cloud, result.labels, kWall, 12), 0.98);
  EXPECT_GE(share_labelled(cloud, result.labels, kTable, 13), 0.98);
  EXPECT_GE(share_labelled(cloud, result.labels, kCabinet, 13), 0.98);

  // Region growing may split a surface into several planes; each is classed alone.
  for (std::size_t k = 0; k < mesh.planes.size(); ++k) {
    const EstimatedPlane& plane = mesh.planes[k];
    const BaselineClass c = result.plane_classes[k];
    if (c == BaselineClass::kWall) {
      EXPECT_LT(std::abs(plane.normal.z()), 0.01);
    } else if (c == BaselineClass::kFloor) {
      EXPECT_NEAR(plane.centroid.z(), 0.0, 0.01);
    } else if (c == BaselineClass::kCeiling) {
      EXPECT_NEAR(plane.centroid.z(), 2.5, 0.01);
    }
  }
  std::size_t counted = 0;
  for (const auto n : result.points) counted += n;
  EXPECT_EQ(counted, cloud.size());
}

TEST(BaselineSegmenter, DefaultIdsAreTheSeedTablesEvaluationIds) {
  const BaselineOptions options;
  EXPECT_EQ(options.wall_id, 0);
  EXPECT_EQ(options.floor_id, 1);
  EXPECT_EQ(options.ceiling_id, 1);
  EXPECT_EQ(options.clutter_id, 25);
  EXPECT_STREQ(kBaselineSegmenterName, "baseline (geometric, region-growing planes)");
}

TEST(BaselineSegmenter, NoPlanesMeansEverythingIsClutter) {
  const PointCloud cloud = box_room();
  const BaselineSegmentation result = segment_baseline(cloud, MeshEstimate{});
  EXPECT_EQ(result.labels, std::vector<std::int32_t>(cloud.size(), 25));
  EXPECT_EQ(result.points[static_cast<std::size_t>(BaselineClass::kClutter)], cloud.size());
}

TEST(BaselineSegmenter, RejectsClusterIdsOfAnotherCloud) {
  const PointCloud cloud = box_room();
  MeshEstimate mesh;
  mesh.point_cluster.assign(cloud.size() - 1, -1);
  EXPECT_THROW(segment_baseline(cloud, mesh), std::invalid_argument);
  BaselineOptions bad;
  bad.max_tilt_degrees = 60.0;
  EXPECT_THROW(segment_baseline(cloud, MeshEstimate{}, bad), std::invalid_argument);
}

// The same room in a camera frame (x right, y down, z forward), as Kinect
// data come: with up -y it is labelled as the z-up room is; with the default
// +z, the data say that up is wrong.
TEST(BaselineSegmenter, CameraFrameRoomNeedsUpMinusY) {
  PointCloud cloud = box_room();
  for (auto& p : cloud.positions) p = Eigen::Vector3f(p.x(), -p.z(), p.y());
  const MeshEstimate mesh = estimate(cloud);
  BaselineOptions options = distinct_ids();
  options.up = UpAxis::parse("-y");
  const BaselineSegmentation right = segment_baseline(cloud, mesh, options);
  EXPECT_TRUE(right.warnings.empty());
  EXPECT_GE(share_labelled(cloud, right.labels, kFloor, 10), 0.98);
  EXPECT_GE(share_labelled(cloud, right.labels, kCeiling, 11), 0.98);
  EXPECT_GE(share_labelled(cloud, right.labels, kWall, 12), 0.98);
  EXPECT_GE(share_labelled(cloud, right.labels, kTable, 13), 0.98);

  options.up = UpAxis{};  // +z
  const BaselineSegmentation wrong = segment_baseline(cloud, mesh, options);
  ASSERT_EQ(wrong.warnings.size(), 1u);
  EXPECT_NE(wrong.warnings[0].find("perpendicular to y"), std::string::npos);
  EXPECT_LT(share_labelled(cloud, wrong.labels, kFloor, 10), 0.5);
}

}  // namespace
}  // namespace occlusion
