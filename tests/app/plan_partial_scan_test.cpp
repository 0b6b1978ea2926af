// Planning on one partial station scan (issue 41): a scanner that recorded
// only half its turn leaves most directions from any position unmeasured, so
// the free-space probes escape and every candidate seemed outside the scene.
// The scan's own station keeps what it saw to be empty. When nothing is kept
// the refusal says, for each reason, what to do.

#include <gtest/gtest.h>

#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/plan_job.hpp"
#include "support/e57_writer.hpp"
#include "support/mesh_truth.hpp"
#include "support/plan_request.hpp"

namespace occlusion {
namespace {

const Eigen::Vector3d kOrigin(1.5, 2.5, 1.5);

// The furnished 6 x 5 x 3 room scanned from kOrigin over part of a turn:
// azimuths from 0 (+x) to `span` (half a turn: the half y > 2.5).
PointCloud partial_scan(double span, bool with_station) {
  const Eigen::Vector3d origin = kOrigin;
  PointCloud cloud =
      testing::station_scan(testing::furnished_room(), origin, 0.015, 0.015, span).cloud;
  if (with_station) {
    Station station{"Station 01", {}};
    station.frame.origin = origin;
    cloud.stations = {station};
  }
  return cloud;
}

PlanRequest best_one() {
  PlanRequest request = testing::plan_mesh_request();
  request.stations = 1;
  request.target_coverage = 0.0;
  return request;
}

TEST(PlanPartialScan, TheStationKeepsTheCandidatesItsScanSawEmpty) {
  const PlanReport report = plan_cloud(partial_scan(M_PI, true), best_one());
  // Without the station only positions near the far corners, whose probes
  // meet the walls the scan saw, are kept.
  const PlanReport without = plan_cloud(partial_scan(M_PI, false), best_one());
  EXPECT_GT(report.candidates.positions.size(), 2 * without.candidates.positions.size());
  EXPECT_LT(report.candidates.rejected.outside, without.candidates.rejected.outside / 5);
  // Every kept position stands in the room, on the side the scan saw (y above
  // the station's, less the probes' reach), clear of the walls.
  for (const auto& p : report.candidates.positions) {
    EXPECT_GT(p.x(), 0.3);
    EXPECT_LT(p.x(), 5.7);
    EXPECT_GT(p.y(), 2.0) << p.transpose();
    EXPECT_LT(p.y(), 4.7);
  }
  // The scan's station is placed first; the new one adds what it hid.
  ASSERT_EQ(report.selection.stations.size(), 2u);
  EXPECT_TRUE(report.selection.stations[0].existing);
  EXPECT_GT(report.selection.stations[1].gain, 0.0);
}

TEST(PlanPartialScan, AnE57FileOfHalfATurnPlansItsNextStation) {
  // As a scanner's file holds it: the points in the scanner's frame, the
  // pose placing it at the station.
  const PointCloud scan = partial_scan(M_PI, false);
  std::vector<double> x, y, z;
  for (const Eigen::Vector3f& p : scan.positions) {
    const Eigen::Vector3d local = p.cast<double>() - kOrigin;
    x.push_back(local.x());
    y.push_back(local.y());
    z.push_back(local.z());
  }
  test::E57ScanSpec spec;
  spec.name = "Station 01";
  spec.rotation = Eigen::Quaterniond::Identity();
  spec.translation = kOrigin;
  spec.fields = {test::e57_double("cartesianX", x), test::e57_double("cartesianY", y),
                 test::e57_double("cartesianZ", z)};
  spec.packets = 64;  // a data packet holds at most 64 KiB
  const testing::ScratchDirectory dir;
  const std::string path = dir.file("station.e57");
  test::E57FileSpec file;
  file.scans = {spec};
  test::write_e57(path, file);

  PlanRequest request = best_one();
  request.path = path;
  const PlanReport report = run_plan(request);
  // Without what the station saw empty half the grid was outside.
  EXPECT_LT(report.candidates.rejected.outside, report.candidates.tested / 10);
  EXPECT_GT(report.candidates.positions.size(), 100u);
  ASSERT_EQ(report.placed.size(), 1u);
  EXPECT_EQ(report.candidate_names.at(report.placed[0]), "Station 01");
  ASSERT_EQ(report.selection.stations.size(), 2u);
  EXPECT_FALSE(report.selection.stations[1].existing);
}

TEST(PlanPartialScan, TheRefusalSaysWhatToDoForEachReason) {
  // A floor and a pipe across it at the scanner's height, with no wall:
  // positions near the pipe, and the rest open all round.
  PointCloud cloud;
  for (double u = 0.025; u < 6.0; u += 0.05) {
    for (double v = 0.025; v < 5.0; v += 0.05) cloud.positions.emplace_back(u, v, 0.0);
  }
  for (double v = 0.0; v < 5.0; v += 0.01) cloud.positions.emplace_back(3.0, v, 1.5);
  PlanRequest request = best_one();
  request.frame = "bbox";  // the pipe's few points are beyond the robust frame's top
  try {
    plan_cloud(cloud, request);
    FAIL() << "a candidate was kept";
  } catch (const UsageError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("outside the scene"), std::string::npos) << message;
    EXPECT_NE(message.find("--candidates"), std::string::npos) << message;
    EXPECT_NE(message.find("nearer than --clearance"), std::string::npos) << message;
    EXPECT_NE(message.find("lower --clearance"), std::string::npos) << message;
    // No solid is tested in a cloud: that reason is not listed.
    EXPECT_EQ(message.find("inside closed solids"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace occlusion
