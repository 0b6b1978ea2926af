// An E57 file end to end: a terrestrial scan of the furnished room, stored as
// a scanner stores it (spherical coordinates in the scanner's own frame, the
// pose turning and placing it, the row and column of each point), read and
// scanned by -fscan with no viewpoint given. Its station is the viewpoint and
// keeps its points; from elsewhere the scan still hides what the room's mesh
// hides (both directions).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/app/in_memory_jobs.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "support/e57_writer.hpp"
#include "support/mesh_truth.hpp"

namespace occlusion {
namespace {

using testing::furnished_room;
using testing::mesh_visibility;
using testing::SampledCloud;
using testing::ScratchDirectory;
using testing::station_scan;

constexpr double kColumnStep = 0.02, kRowStep = 0.004;  // radians, as the scan was taken

// The scan as the scanner's file holds it: each point in the scanner's frame
// (R^T (p - t)) as range, azimuth and elevation, with its grid cell.
test::E57ScanSpec as_scanner_stores(const SampledCloud& scan, const Eigen::Quaterniond& rotation,
                                    const Eigen::Vector3d& translation) {
  std::vector<double> range, azimuth, elevation;
  std::vector<std::int64_t> row, column;
  std::int64_t rows = 0, columns = 0;
  for (const Eigen::Vector3f& p : scan.cloud.positions) {
    const Eigen::Vector3d local = rotation.conjugate() * (p.cast<double>() - translation);
    const double r = local.norm();
    range.push_back(r);
    azimuth.push_back(std::atan2(local.y(), local.x()));
    elevation.push_back(std::asin(local.z() / r));
    column.push_back(std::lround((azimuth.back() + M_PI) / kColumnStep));
    row.push_back(std::lround((elevation.back() + M_PI / 2) / kRowStep));
    rows = std::max(rows, row.back() + 1);
    columns = std::max(columns, column.back() + 1);
  }
  test::E57ScanSpec spec;
  spec.name = "Station 01";
  spec.rotation = rotation;
  spec.translation = translation;
  spec.fields = {test::e57_double("sphericalRange", range),
                 test::e57_double("sphericalAzimuth", azimuth),
                 test::e57_double("sphericalElevation", elevation),
                 test::e57_integer("rowIndex", 0, rows - 1, row),
                 test::e57_integer("columnIndex", 0, columns - 1, column)};
  spec.packets = 256;  // a data packet holds at most 64 KiB
  return spec;
}

TEST(E57StationScan, ItsStationIsTheViewpointAndKeepsItsPointsWhileWallsStillHide) {
  const TriangleMesh mesh = furnished_room();
  const Eigen::Vector3d station(1.0, 1.0, 1.6);
  const SampledCloud scan = station_scan(mesh, station, kColumnStep, kRowStep);
  // The scanner stood turned 30 degrees about its vertical axis.
  const Eigen::Quaterniond rotation(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()));
  const ScratchDirectory dir;
  const std::string path = dir.file("station.e57");
  test::E57FileSpec file;
  file.scans = {as_scanner_stores(scan, rotation, station)};
  test::write_e57(path, file);

  // Read back: the points where the scanner measured them, the station recorded.
  const PointCloud cloud = read_cloud(path);
  ASSERT_EQ(cloud.size(), scan.cloud.size());
  for (std::size_t i = 0; i < cloud.size(); i += 997) {
    EXPECT_LT((cloud.positions[i] - scan.cloud.positions[i]).norm(), 1e-5) << i;
  }
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_LT((cloud.stations[0].frame.origin - station).norm(), 1e-9);

  // -fscan of the file, no viewpoint given: seen from its station, through its window.
  ScanRequest request;
  request.path = path;
  const ScanReport own = run_scan(request);
  EXPECT_EQ(own.viewpoint_names, (std::vector<std::string>{"Station 01"}));
  EXPECT_GE(own.result.visible_fraction, 0.99);
  ASSERT_TRUE(own.field_of_view);
  EXPECT_TRUE(own.field_of_view->full_turn);

  // From above the furniture, what the mesh hides behind the cabinet, the
  // board and the walls is dropped, and what it sees is kept.
  const Eigen::Vector3d high(3.0, 2.5, 2.6);
  SampledCloud read = scan;
  read.cloud = cloud;
  ViewpointChoice::Resolved viewpoint;
  viewpoint.positions = {high};
  viewpoint.names = {"high"};
  const ScanReport other = run_scan_on(cloud, viewpoint, request);
  const std::vector<std::uint8_t> truth = mesh_visibility(mesh, read, high);
  std::size_t visible = 0, kept = 0, hidden = 0, dropped = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const bool seen = other.result.visible_count[i] > 0;
    visible += truth[i];
    kept += truth[i] && seen;
    hidden += !truth[i];
    dropped += !truth[i] && !seen;
  }
  ASSERT_GT(hidden, 1000u);  // the room hides much of this scan from there
  EXPECT_GE(static_cast<double>(kept) / visible, 0.95);
  EXPECT_GE(static_cast<double>(dropped) / hidden, 0.9);
}

}  // namespace
}  // namespace occlusion
