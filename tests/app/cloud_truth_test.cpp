// Clouds give the answers their surfaces give: -fscan and -poc with their
// default settings (discs) on clouds sampled from a furnished room, judged
// against the room's mesh traced exactly. Both directions: what a viewpoint
// sees is kept, and what a wall, a cabinet or a board hides is not. Spheres
// (primitive sphere) are the control: the error this model was built to remove.

#include <gtest/gtest.h>

#include <string>

#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/in_memory_jobs.hpp"
#include "occlusion/app/scan_job.hpp"
#include "support/mesh_truth.hpp"

namespace occlusion {
namespace {

using testing::furnished_room;
using testing::mesh_escape_share;
using testing::mesh_visibility;
using testing::sample_room;
using testing::SampledCloud;
using testing::station_scan;

// Above the furniture, and low among it (seeing the floor at grazing angles).
const Eigen::Vector3d kHigh(3.0, 2.5, 2.6);
const Eigen::Vector3d kLow(2.2, 3.4, 0.35);

ViewpointChoice::Resolved at(const std::vector<Eigen::Vector3d>& positions) {
  ViewpointChoice::Resolved resolved;
  resolved.positions = positions;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    resolved.names.push_back("v" + std::to_string(v));
  }
  return resolved;
}

struct Agreement {
  double agreement = 0.0;         // share of points where the scan says what the mesh says
  double visible = 0.0;           // the scan's visible fraction
  double truth = 0.0;             // the mesh's
  double kept_of_visible = 0.0;   // of the points the mesh sees, the share the scan keeps
  double hidden_of_hidden = 0.0;  // of the points the mesh hides, the share the scan drops
};

Agreement scan_against_mesh(const TriangleMesh& mesh, const SampledCloud& sampled,
                            const Eigen::Vector3d& viewpoint, const std::string& primitive) {
  ScanRequest request;
  request.path = "room";
  request.primitive = primitive;
  const ScanReport report = run_scan_on(sampled.cloud, at({viewpoint}), request);
  const std::vector<std::uint8_t> truth = mesh_visibility(mesh, sampled, viewpoint);
  std::size_t same = 0, seen = 0, visible = 0, kept = 0, hidden = 0, dropped = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const bool scan_sees = report.result.visible_count[i] > 0;
    same += scan_sees == (truth[i] != 0);
    seen += scan_sees;
    visible += truth[i];
    kept += truth[i] && scan_sees;
    hidden += !truth[i];
    dropped += !truth[i] && !scan_sees;
  }
  const auto n = static_cast<double>(truth.size());
  return {same / n, seen / n, visible / n, static_cast<double>(kept) / visible,
          static_cast<double>(dropped) / hidden};
}

void expect_scan_matches_mesh(const TriangleMesh& mesh, const SampledCloud& sampled,
                              const std::string& what) {
  for (const Eigen::Vector3d& viewpoint : {kHigh, kLow}) {
    const Agreement a = scan_against_mesh(mesh, sampled, viewpoint, "disc");
    const std::string where = what + " from " + std::to_string(viewpoint.z());
    EXPECT_GE(a.agreement, 0.97) << where;
    EXPECT_NEAR(a.visible, a.truth, 0.02) << where;
    // Both directions: the visible are kept and the hidden dropped (discs
    // close 99 % of a surface by default, and a thin board's far side or a
    // grazing view costs more).
    EXPECT_GE(a.kept_of_visible, 0.95) << where;
    EXPECT_GE(a.hidden_of_hidden, 0.9) << where;
  }
}

TEST(CloudTruth, ScanOfUniformSamplesAgreesWithTheMesh) {
  const TriangleMesh mesh = furnished_room();
  expect_scan_matches_mesh(mesh, sample_room(mesh, 1000.0, 1), "uniform");
}

TEST(CloudTruth, ScanOfSamplesThinningFourfoldAgreesWithTheMesh) {
  const TriangleMesh mesh = furnished_room();
  expect_scan_matches_mesh(mesh, sample_room(mesh, 2000.0, 2, 4.0), "falloff");
}

TEST(CloudTruth, ScanOfAFiveToOneGridAgreesWithTheMesh) {
  const TriangleMesh mesh = furnished_room();
  // Rows five times closer than columns, as a terrestrial scanner's, jittered.
  expect_scan_matches_mesh(mesh, testing::grid_sample_room(mesh, 0.01, 0.05, 0.004, 6), "5:1 grid");
}

TEST(CloudTruth, StationScanKeepsItsPointsAndClosesWhatItSaw) {
  const TriangleMesh mesh = furnished_room();
  const Eigen::Vector3d station(1.0, 1.0, 1.6);
  // Columns 0.02 rad apart, rows 0.004: spacing 5:1 and growing with range.
  const SampledCloud scan = station_scan(mesh, station, 0.02, 0.004);
  ScanRequest request;
  request.path = "station";
  const ScanReport own = run_scan_on(scan.cloud, at({station}), request);
  EXPECT_GE(own.result.visible_fraction, 0.99);
  // Rays from the station into what it scanned (all but the poles above and
  // below 85 degrees, 0.4 % of the sphere) meet the scan's surfaces.
  CloudOcclusionRequest poc;
  poc.path = "station";
  poc.num_rays_per_vp = 20000;
  const CloudOcclusionReport closed = run_cloud_occlusion_on(scan.cloud, at({station}), {}, poc);
  EXPECT_LE(closed.result.occlusion_level, 0.02);
}

TEST(CloudTruth, StationScanRecordingItsStationIsSeenFromItThroughItsWindow) {
  const TriangleMesh mesh = furnished_room();
  const Eigen::Vector3d station(1.0, 1.0, 1.6);
  SampledCloud scan = station_scan(mesh, station, 0.02, 0.004);
  // As an E57 scan records it: the pose and the grid, 315 columns of 742 rows.
  Station recorded{"station 1", {}};
  recorded.frame.origin = station;
  recorded.frame.width = 315;
  recorded.frame.height = 742;
  scan.cloud.stations = {recorded};
  ScanRequest request;
  request.path = "station";
  const ScanReport own = scan_in_memory(scan.cloud, request);  // no viewpoint given
  EXPECT_EQ(own.viewpoint_names, (std::vector<std::string>{"station 1"}));
  EXPECT_GE(own.result.visible_fraction, 0.99);
  // Its window: elevations -85 to 84.8 degrees widened by half a row (0.11
  // degrees), a full turn; none of its own points lies outside it.
  ASSERT_TRUE(own.field_of_view);
  EXPECT_NEAR(own.field_of_view->elevation_lo_degrees(), -85.11, 0.01);
  EXPECT_NEAR(own.field_of_view->elevation_hi_degrees(), 84.94, 0.01);
  EXPECT_TRUE(own.field_of_view->full_turn);
  EXPECT_EQ(own.result.outside_view_rays, 0u);
  EXPECT_EQ(to_json(own)["station_field_of_view"]["station"].asString(), "station 1");
  // Both directions from elsewhere, through the same window. From above the
  // furniture, what the mesh sees is kept and what a wall, the cabinet or the
  // board hides is dropped. The window takes away only directions the scanner
  // never looked in (a 5 degree cone above and below each viewpoint): the
  // same scan without its grid (so without a window, but with its station,
  // which the point model reads too) hides no more and keeps about as much,
  // from above and from low among the furniture (where this scan's sparse
  // columns let through half of what the mesh hides, window or not).
  SampledCloud unrecorded = scan;
  unrecorded.cloud.stations.front().frame.width = 0;
  unrecorded.cloud.stations.front().frame.height = 0;
  for (const Eigen::Vector3d& viewpoint : {kHigh, kLow}) {
    const Agreement with = scan_against_mesh(mesh, scan, viewpoint, "disc");
    const Agreement without = scan_against_mesh(mesh, unrecorded, viewpoint, "disc");
    const std::string where = "from " + std::to_string(viewpoint.z());
    EXPECT_GE(with.hidden_of_hidden, without.hidden_of_hidden) << where;
    EXPECT_NEAR(with.kept_of_visible, without.kept_of_visible, 0.01) << where;
    if (viewpoint == kHigh) {
      EXPECT_GE(with.agreement, 0.95);
      EXPECT_GE(with.kept_of_visible, 0.95);
      EXPECT_GE(with.hidden_of_hidden, 0.9);
    }
  }
}

TEST(CloudTruth, SpheresAreTheErrorDiscsRemove) {
  // The control: the thesis' spheres keep far more points than the mesh sees.
  const TriangleMesh mesh = furnished_room();
  const SampledCloud sampled = sample_room(mesh, 1000.0, 3);
  const Agreement spheres = scan_against_mesh(mesh, sampled, kHigh, "sphere");
  const Agreement discs = scan_against_mesh(mesh, sampled, kHigh, "disc");
  EXPECT_GT(spheres.visible - spheres.truth, 0.05);
  EXPECT_GT(discs.agreement, spheres.agreement + 0.05);
}

TEST(CloudTruth, ClosedRoomHasNoOcclusionRays) {
  const TriangleMesh mesh = furnished_room();
  const SampledCloud sampled = sample_room(mesh, 1000.0, 4);
  CloudOcclusionRequest request;
  request.path = "room";
  request.num_rays_per_vp = 20000;
  const CloudOcclusionReport report =
      run_cloud_occlusion_on(sampled.cloud, at({kHigh, kLow}), {}, request);
  EXPECT_LE(report.result.occlusion_level, 0.02);
  ASSERT_TRUE(report.point_model.open_surface_share);
  EXPECT_LE(*report.point_model.open_surface_share, 0.01);
}

TEST(CloudTruth, WindowLetsOutItsShareOfRays) {
  const TriangleMesh mesh = furnished_room(/*window=*/true);
  const SampledCloud sampled = sample_room(mesh, 1000.0, 5);
  CloudOcclusionRequest request;
  request.path = "room";
  request.num_rays_per_vp = 40000;
  const std::vector<Eigen::Vector3d> viewpoints = {{4.5, 2.1, 1.5}, kHigh};
  const CloudOcclusionReport report =
      run_cloud_occlusion_on(sampled.cloud, at(viewpoints), {}, request);
  for (std::size_t v = 0; v < viewpoints.size(); ++v) {
    const double truth = mesh_escape_share(mesh, viewpoints[v], v, request.num_rays_per_vp, 0);
    if (v == 0) {
      EXPECT_GT(truth, 0.02);  // the window is in view
    }
    EXPECT_NEAR(report.result.viewpoints[v].occlusion_level, truth, 0.01) << v;
  }
}

}  // namespace
}  // namespace occlusion
