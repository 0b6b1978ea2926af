// Scan planning end to end (issue 28), on scenes whose best plan is known:
// two rooms joined by a door, a room with a central pillar, an empty room,
// a room with a thick wall and a closed cabinet; clouds sampled from them.

#include "occlusion/app/plan_job.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/scratch_directory.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/io/csv_file.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"
#include "support/mesh_truth.hpp"
#include "support/plan_request.hpp"
#include "support/plan_scenes.hpp"

namespace occlusion {
namespace {

std::vector<Eigen::Vector3d> new_positions(const PlanReport& report) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& s : report.selection.stations) {
    if (!s.existing) out.push_back(report.candidate_positions.at(s.candidate));
  }
  return out;
}

TEST(PlanJob, TwoRoomsNeedExactlyTwoStationsOneInEachForNinetyNinePercent) {
  const PlanReport report = plan_mesh(testing::two_rooms(), testing::plan_mesh_request());
  const auto stations = new_positions(report);
  ASSERT_EQ(stations.size(), 2u) << report.selection.guarantee;
  EXPECT_TRUE(report.selection.target_reached);
  EXPECT_GE(report.selection.coverage, 0.99);
  const bool first_in_a = stations[0].x() < 6.25;
  EXPECT_NE(first_in_a, stations[1].x() < 6.25) << "both stations in one room";
  // No single station reaches 99 %: the lower bound says two are needed.
  EXPECT_EQ(report.selection.fewest_stations_bound >= 1, true);
  for (double alone : report.selection.coverage_alone) EXPECT_LT(alone, 0.99);
}

TEST(PlanJob, TheBestSingleStationOfTwoRoomsStandsInTheLargerOne) {
  PlanRequest request = testing::plan_mesh_request();
  request.stations = 1;
  request.target_coverage = 0.0;
  const PlanReport report = plan_mesh(testing::two_rooms(), request);
  const auto stations = new_positions(report);
  ASSERT_EQ(stations.size(), 1u);
  EXPECT_LT(stations[0].x(), 6.25);  // room A, 6.25 x 5 against B's 3.75 x 5
  // It sees all of room A (floor, ceiling, walls: over half the area) and
  // part of B through the door; the bound holds it.
  EXPECT_GT(report.selection.coverage, 0.55);
  EXPECT_LE(report.selection.coverage, report.selection.optimum_coverage_bound);
  // One station is the best one, which says more than greedy's 1 - 1/e.
  EXPECT_NE(report.selection.guarantee.find("adds most among these candidates"), std::string::npos)
      << report.selection.guarantee;
  EXPECT_EQ(report.selection.guarantee.find("1 - 1/e"), std::string::npos);
}

TEST(PlanJob, TheCoverageMatrixCountsInTheMemoryBudget) {
  // 100 targets: two 64-bit words a row, 16 bytes; three rows.
  const MemoryEstimate model{1000, "the model", ""};
  const MemoryEstimate plan = plan_memory(model, 100, 3, false);
  EXPECT_EQ(plan.bytes - plan_memory(model, 100, 0, false).bytes, 3u * 16u);
  // Rows of whole words, as the matrix pads them: 128 targets are two.
  EXPECT_EQ(plan_memory(model, 128, 1, false).bytes - plan_memory(model, 128, 0, false).bytes, 16u);
  // With intervisible, a byte per pair.
  EXPECT_EQ(plan_memory(model, 100, 3, true).bytes - plan.bytes, 9u);
  EXPECT_NE(plan.made_of.find("3 candidates x 100 targets"), std::string::npos) << plan.made_of;
  // A fine grid over a large room: refused before the matrix is filled,
  // naming it and what to lower.
  PlanRequest request = testing::plan_mesh_request();
  request.samples_per_unit_area = 2000.0;
  request.spacing = 0.05;
  request.max_memory_mb = 64;
  try {
    plan_mesh(testing::two_rooms(), request);
    FAIL() << "a plan over the budget ran";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("coverage matrix"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("spacing"), std::string::npos) << error.what();
  }
}

TEST(PlanJob, APillarRoomNeedsTwoStationsOnOppositeSides) {
  const PlanReport report = plan_mesh(testing::pillar_room(), testing::plan_mesh_request());
  const auto stations = new_positions(report);
  ASSERT_EQ(stations.size(), 2u) << report.selection.guarantee;
  EXPECT_GE(report.selection.coverage, 0.99);
  // The pillar's centre lies between them in the floor plan.
  const Eigen::Vector2d centre(3.0, 3.0);
  const Eigen::Vector2d a = stations[0].head<2>() - centre, b = stations[1].head<2>() - centre;
  EXPECT_LT(a.dot(b), 0.0) << stations[0].transpose() << " / " << stations[1].transpose();
  // One station is not enough: the pillar hides part of the room from each.
  for (double alone : report.selection.coverage_alone) EXPECT_LT(alone, 0.99);
}

TEST(PlanJob, AnEmptyRoomIsCoveredByOneStationAnywhereInside) {
  const PlanReport report = plan_mesh(testing::empty_room(), testing::plan_mesh_request());
  EXPECT_EQ(new_positions(report).size(), 1u);
  EXPECT_GT(report.candidates.positions.size(), 20u);
  for (double alone : report.selection.coverage_alone) EXPECT_GE(alone, 0.999);
}

TEST(PlanJob, CandidatesInsideWallsOrFurnitureAreNeverChosen) {
  PlanRequest request = testing::plan_mesh_request();
  request.stations = 3;
  request.target_coverage = 0.0;
  request.spacing = 0.25;
  const PlanReport report = plan_mesh(testing::room_with_solids(), request);
  EXPECT_GT(report.candidates.rejected.clearance, 0u);
  const auto inside = [](const Eigen::Vector3d& p, Eigen::Vector3d lo, Eigen::Vector3d hi) {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  };
  for (const auto& p : report.candidate_positions) {
    EXPECT_FALSE(inside(p, {2.9, 0, 0}, {3.1, 4, 3})) << p.transpose();
    EXPECT_FALSE(inside(p, {4, 1, 0}, {5.2, 2.2, 2})) << p.transpose();
  }
  EXPECT_EQ(new_positions(report).size(), 3u);
}

TEST(PlanJob, TheSameSeedGivesTheSamePlanWhateverTheThreads) {
  PlanRequest request = testing::plan_mesh_request();
  request.seed = 11;
  request.threads = 1;
  const PlanReport a = plan_mesh(testing::pillar_room(), request);
  request.threads = 2;
  const PlanReport b = plan_mesh(testing::pillar_room(), request);
  ASSERT_EQ(a.selection.stations.size(), b.selection.stations.size());
  for (std::size_t i = 0; i < a.selection.stations.size(); ++i) {
    EXPECT_EQ(a.selection.stations[i].candidate, b.selection.stations[i].candidate);
    EXPECT_EQ(a.selection.stations[i].coverage, b.selection.stations[i].coverage);
  }
  EXPECT_EQ(a.selection.first_rank, b.selection.first_rank);
}

TEST(PlanJob, ACloudSampledFromTheTwoRoomsGetsTheMeshsStations) {
  const TriangleMesh mesh = testing::two_rooms();
  PointCloud cloud = testing::sample_room(mesh, 150.0, 8).cloud;
  PlanRequest request = testing::plan_mesh_request();
  request.stations = 1;
  request.target_coverage = 0.0;
  const PlanReport from_mesh = plan_mesh(mesh, request);
  const PlanReport from_cloud = plan_cloud(cloud, request);
  // The same candidates survive (the grid is 0.25 from the door wall or
  // 0.5 and more from any surface), so indices compare.
  ASSERT_EQ(from_mesh.candidate_positions.size(), from_cloud.candidate_positions.size());
  ASSERT_EQ(from_cloud.selection.stations.size(), 1u);
  EXPECT_EQ(from_cloud.selection.stations[0].candidate, from_mesh.selection.stations[0].candidate);
  EXPECT_NEAR(from_cloud.selection.coverage, from_mesh.selection.coverage, 0.03);

  PlanRequest target = testing::plan_mesh_request();
  const PlanReport mesh_target = plan_mesh(mesh, target);
  const PlanReport cloud_target = plan_cloud(cloud, target);
  const auto m = new_positions(mesh_target), c = new_positions(cloud_target);
  ASSERT_EQ(c.size(), m.size());
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NE(c[0].x() < 6.25, c[1].x() < 6.25);
  EXPECT_EQ(cloud_target.targets, "points");
  ASSERT_TRUE(cloud_target.point_model.has_value());
  EXPECT_EQ(cloud_target.point_model->primitive, "disc");
}

TEST(PlanJob, ACloudsOwnStationsArePlacedFirstUnlessTurnedOff) {
  PointCloud cloud = testing::sample_room(testing::two_rooms(), 150.0, 9).cloud;
  Station station{"scan_a", {}};
  station.frame.origin = Eigen::Vector3d(3.0, 2.5, 1.5);
  cloud.stations = {station};
  const PlanReport report = plan_cloud(cloud, testing::plan_mesh_request());
  ASSERT_GE(report.selection.stations.size(), 2u);
  EXPECT_TRUE(report.selection.stations[0].existing);
  EXPECT_EQ(report.candidate_names.at(report.selection.stations[0].candidate), "scan_a");
  // The one new station goes to room B.
  const auto added = new_positions(report);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_GT(added[0].x(), 6.25);

  PlanRequest off = testing::plan_mesh_request();
  off.existing_stations = false;
  EXPECT_TRUE(plan_cloud(cloud, off).placed.empty());
}

TEST(PlanJob, WritesTheReportTheCurveTheCandidatesAndTheTargetsWithTheirFirstStation) {
  testing::ScratchDirectory dir;
  const std::string scene = (dir.path() / "rooms.ply").string();
  // A PLY with faces is a mesh (a PLY of points would be a cloud).
  const TriangleMesh mesh = testing::two_rooms();
  write_mesh_ply(scene, mesh, std::vector<float>(mesh.face_count(), 0.0f), "value");
  PlanRequest request = testing::plan_mesh_request();
  request.path = scene;
  request.out = (dir.path() / "out").string();
  const PlanReport report = run_plan(request);
  ASSERT_EQ(report.outputs.size(), 4u);
  for (const auto& path : report.outputs) EXPECT_TRUE(std::filesystem::exists(path)) << path;
  const CsvTable curve = read_csv(report.outputs[1]);
  EXPECT_EQ(curve.rows.size(), report.selection.stations.size());
  const CsvTable candidates = read_csv(report.outputs[2]);
  EXPECT_EQ(candidates.rows.size(), report.candidate_positions.size());
  std::ifstream ply(report.outputs[3]);
  std::string header((std::istreambuf_iterator<char>(ply)), {});
  header = header.substr(0, header.find("end_header"));
  // The writers' name for a per-point value (CloudCompare shows it as first_station).
  EXPECT_NE(header.find("property int scalar_" + std::string(kFirstStationField) + "\n"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find("element vertex " + std::to_string(report.target_count)), std::string::npos)
      << header;
  const Json::Value json = to_json(report);
  EXPECT_EQ(json["job"].asString(), "plan");
  EXPECT_EQ(json["stations"].size(), 2u);
  EXPECT_EQ(json["coverage_curve"].size(), 2u);
  EXPECT_EQ(json["targets"].asString(), "samples");
  EXPECT_EQ(json["candidates"]["gain_left"].size(), report.candidate_positions.size());
}

TEST(PlanJob, RefusesAQuestionItCannotAnswer) {
  PlanRequest request = testing::plan_mesh_request();
  request.target_coverage = 0.0;  // neither question
  EXPECT_THROW(plan_mesh(testing::empty_room(), request), UsageError);
  PlanRequest classes = testing::plan_mesh_request();
  classes.classes = {"window"};
  EXPECT_THROW(plan_mesh(testing::empty_room(), classes), UsageError);
  PlanRequest crowded = testing::plan_mesh_request();
  crowded.clearance = 10.0;
  EXPECT_THROW(plan_mesh(testing::empty_room(), crowded), UsageError);
}

// A target the selection cannot tell from rounding was "reached" with no
// station, at coverage 0: it is refused, naming the key.
TEST(PlanJob, ATargetTooSmallToTellFromRoundingIsRefusedNamingTheKey) {
  for (const double tiny : {1e-300, 1e-13}) {
    PlanRequest request = testing::plan_mesh_request();
    request.target_coverage = tiny;
    try {
      const PlanReport report = plan_mesh(testing::empty_room(), request);
      ADD_FAILURE() << tiny << ": reached " << report.selection.target_reached << " at coverage "
                    << report.selection.coverage;
    } catch (const KeyError& e) {
      EXPECT_EQ(e.key, "target_coverage") << e.what();
    }
  }
  // The least target still takes a station that covers something.
  PlanRequest least = testing::plan_mesh_request();
  least.target_coverage = 1e-9;
  const PlanReport report = plan_mesh(testing::empty_room(), least);
  EXPECT_TRUE(report.selection.target_reached);
  ASSERT_EQ(new_positions(report).size(), 1u);
  EXPECT_GT(report.selection.coverage, 0.0);
}

TEST(PlanJob, IsARegistryJobWithItsKeysOnEveryFace) {
  const JobInfo* job = find_job("plan");
  ASSERT_NE(job, nullptr);
  EXPECT_EQ(job->section, "plan");
  bool stations = false, target = false;
  for (const auto& info : job->keys) {
    stations |= info.name == "stations";
    target |= info.name == "target_coverage";
  }
  EXPECT_TRUE(stations && target);
}

}  // namespace
}  // namespace occlusion
