#include "occlusion/analysis/station_candidates.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/mesh_truth.hpp"
#include "support/plan_scenes.hpp"

namespace occlusion {
namespace {

using testing::l_room;
using testing::room_with_solids;

// Is p nearer than `margin` to the box [lo, hi] (or inside it)? A negative
// margin: is it at least -margin inside.
bool in_box(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
            double margin) {
  if (margin < 0.0) {
    return (p.array() > lo.array() - margin).all() && (p.array() < hi.array() + margin).all();
  }
  const Eigen::Vector3d outside = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
  return outside.norm() < margin;
}

TEST(StationCandidates, FloorGridIsSpacedCentredAndAtHeightAboveTheFloor) {
  Box frame{{0, 0, 1}, {4.2, 3, 3.5}};
  const auto grid = floor_grid(frame, UpAxis{}, 1.0, 1.5);
  ASSERT_EQ(grid.size(), 5u * 4u);
  for (const auto& p : grid) EXPECT_DOUBLE_EQ(p.z(), 2.5);
  // Centred: 0.1 from both x walls, on the y walls.
  EXPECT_NEAR(grid.front().x(), 0.1, 1e-12);
  EXPECT_NEAR(grid[4].x(), 4.1, 1e-12);
  EXPECT_NEAR(grid[1].x() - grid[0].x(), 1.0, 1e-12);
  EXPECT_NEAR(grid.back().y(), 3.0, 1e-12);

  // Up -y (camera frames): the floor is the high end of y; the plan is z, x.
  Box camera{{0, -3, 0}, {4, 0, 5}};
  const auto under = floor_grid(camera, UpAxis::parse("-y"), 1.0, 1.5);
  ASSERT_EQ(under.size(), 6u * 5u);
  for (const auto& p : under) EXPECT_DOUBLE_EQ(p.y(), -1.5);

  EXPECT_THROW(floor_grid(frame, UpAxis{}, 1.0, 2.6), std::invalid_argument);  // above the top
  EXPECT_THROW(floor_grid(frame, UpAxis{}, 0.0, 1.5), std::invalid_argument);
  EXPECT_THROW(floor_grid(frame, UpAxis{}, 1e-3, 1.5), std::invalid_argument);  // too many
}

TEST(StationCandidates, PositionsInAWallInAClosedCabinetOrOutsideAreRejectedWithTheirReason) {
  const TriangleMesh mesh = room_with_solids();
  const std::vector<Eigen::Vector3d> positions = {
      {3.0, 2.0, 1.5},   // in the thick wall
      {4.6, 1.6, 1.0},   // in the cabinet, 0.6 m from its sides
      {12.0, 2.0, 1.5},  // outside the room
      {1.5, 2.5, 1.5},   // free
  };
  const StationCandidates kept = keep_free_positions(mesh, positions, 0.3, UpAxis{});
  EXPECT_EQ(kept.tested, 4u);
  ASSERT_EQ(kept.positions.size(), 1u);
  EXPECT_EQ(kept.positions[0], positions[3]);
  EXPECT_EQ(kept.rejected.clearance, 1u);
  EXPECT_EQ(kept.rejected.inside_solid, 1u);
  EXPECT_EQ(kept.rejected.outside, 1u);
}

TEST(StationCandidates, NoGridPositionInsideSolidsOrNearerThanTheClearanceIsKept) {
  const TriangleMesh mesh = room_with_solids();
  const double clearance = 0.3;
  Box box;
  mesh.bounds(box.lo, box.hi);
  const auto grid = floor_grid(box, UpAxis{}, 0.25, 1.2);
  const StationCandidates kept = keep_free_positions(mesh, grid, clearance, UpAxis{});
  EXPECT_GT(kept.rejected.clearance, 0u);
  std::size_t left = 0, right = 0;
  for (const auto& p : kept.positions) {
    EXPECT_FALSE(in_box(p, {2.9, 0, 0}, {3.1, 4, 3}, clearance)) << p.transpose();
    EXPECT_FALSE(in_box(p, {4, 1, 0}, {5.2, 2.2, 2}, clearance)) << p.transpose();
    EXPECT_TRUE(in_box(p, {0, 0, 0}, {6, 5, 3}, -clearance)) << p.transpose();
    (p.x() < 3 ? left : right) += 1;
  }
  EXPECT_GT(left, 10u);
  EXPECT_GT(right, 10u);
}

TEST(StationCandidates, NothingOutsideAnLShapedRoomIsKeptFromItsMeshOrItsCloud) {
  const TriangleMesh mesh = l_room();
  Box box;
  mesh.bounds(box.lo, box.hi);
  const auto grid = floor_grid(box, UpAxis{}, 0.5, 1.5);
  const auto check = [&](const StationCandidates& kept) {
    EXPECT_GT(kept.rejected.outside, 50u);
    std::size_t arm_x = 0, arm_y = 0;
    for (const auto& p : kept.positions) {
      EXPECT_FALSE(p.x() > 5.0 && p.y() > 5.0) << "in the missing corner: " << p.transpose();
      arm_x += p.x() > 5.5 ? 1 : 0;
      arm_y += p.y() > 5.5 ? 1 : 0;
    }
    EXPECT_GT(arm_x, 50u);
    EXPECT_GT(arm_y, 50u);
  };
  {
    SCOPED_TRACE("mesh");
    check(keep_free_positions(mesh, grid, 0.3, UpAxis{}));
  }
  {
    SCOPED_TRACE("cloud");
    const PointCloud cloud = testing::sample_room(mesh, 100.0, 5).cloud;
    check(keep_free_positions(cloud, grid, 0.3, UpAxis{}));
  }
}

// The clearance test of a fine grid against a mesh of many faces takes
// seconds: it reports progress (where Python polls Ctrl-C) and stops at a
// cancel within a small share of it. It reported nothing, and the
// inside-solid probes of every position ran before the first report
// (issue 44, 2.10: Ctrl-C took effect 5-14 s late).
TEST(StationCandidates, ACancelStopsTheClearanceTestWithinASmallShareOfIt) {
  TriangleMesh room;
  testing::add_box(room, {0, 0, 0}, {10, 10, 3}, "room", 40);  // 19,200 faces
  std::vector<Eigen::Vector3d> positions;
  for (int i = 0; i < 50; ++i) {
    for (int j = 0; j < 40; ++j) positions.emplace_back(0.1 + 0.2 * i, 0.1 + 0.25 * j, 1.5);
  }
  std::atomic<bool> cancel{false};
  double at_cancel = -1.0;
  std::vector<std::string> after_cancel;
  Progress progress;
  progress.cancel = &cancel;
  progress.report = [&](const std::string& stage, double fraction) {
    if (cancel) {
      after_cancel.push_back(stage);
    } else if (stage == "clearance" && fraction > 0.0) {
      at_cancel = fraction;
      cancel = true;
    }
  };
  EXPECT_THROW(keep_free_positions(room, positions, 0.3, UpAxis{}, 2, progress), Cancelled);
  EXPECT_GT(at_cancel, 0.0);
  EXPECT_LT(at_cancel, 0.2);
  EXPECT_TRUE(after_cancel.empty()) << after_cancel.front() << " after the cancel";
}

TEST(StationCandidates, RefusesAnEmptySceneOrANegativeClearance) {
  EXPECT_THROW(keep_free_positions(PointCloud{}, {{0, 0, 0}}, 0.3, UpAxis{}),
               std::invalid_argument);
  EXPECT_THROW(keep_free_positions(TriangleMesh{}, {{0, 0, 0}}, 0.3, UpAxis{}),
               std::invalid_argument);
  EXPECT_THROW(keep_free_positions(testing::l_room(), {{1, 1, 1}}, -1.0, UpAxis{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
