#include "occlusion/analysis/scene_frame.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/core/random.hpp"
#include "support/cloud_scenes.hpp"

namespace occlusion {
namespace {

// The room [0, 4] x [0, 3] x [0, 2.5] sampled every 5 cm, plus `strays`
// points scattered over a 30 x 14 x 6 m box around it (a real scan's
// reflections and passers-by).
PointCloud room_with_strays(std::size_t strays) {
  PointCloud cloud;
  testing::add_box_grid(cloud, 80, 60, 50, 0.05);
  Rng rng(7);
  for (std::size_t k = 0; k < strays; ++k) {
    cloud.positions.emplace_back(static_cast<float>(-13.0 + 30.0 * rng.uniform()),
                                 static_cast<float>(-5.5 + 14.0 * rng.uniform()),
                                 static_cast<float>(-2.0 + 6.0 * rng.uniform()));
  }
  return cloud;
}

TEST(SceneFrame, RobustBoxIsTheRoomDespiteStrayPoints) {
  const PointCloud cloud = room_with_strays(200);  // 0.7 % of the points
  const SceneFrame frame = measure_scene_frame(cloud.positions);
  const Eigen::Vector3d room(4.0, 3.0, 2.5);
  // The quantile falls inside the outermost wall's layer: exactly on it here.
  EXPECT_TRUE(frame.robust.lo.isZero(1e-6)) << frame.robust.lo.transpose();
  EXPECT_TRUE(frame.robust.hi.isApprox(room, 1e-6)) << frame.robust.hi.transpose();
  EXPECT_LT(frame.bbox.lo.x(), -10.0);
  EXPECT_GT(frame.bbox.hi.x(), 14.0);

  // Pattern 7 lands in the room on the robust box, two of three outside on the bbox.
  for (const auto& p : pattern_viewpoints(7, frame.robust.lo, frame.robust.hi)) {
    EXPECT_TRUE(frame.robust.contains(p)) << p.transpose();
  }
  Box room_box;
  room_box.hi = room;
  int outside = 0;
  for (const auto& p : pattern_viewpoints(7, frame.bbox.lo, frame.bbox.hi)) {
    outside += room_box.contains(p) ? 0 : 1;
  }
  EXPECT_GE(outside, 2);
}

TEST(SceneFrame, WithoutStraysBothBoxesAreTheRoom) {
  const SceneFrame frame = measure_scene_frame(room_with_strays(0).positions);
  EXPECT_TRUE(frame.robust.lo.isApprox(frame.bbox.lo, 1e-9));
  EXPECT_TRUE(frame.robust.hi.isApprox(frame.bbox.hi, 1e-9));
}

TEST(SceneFrame, ParsesFrameNamesAndRefusesOthers) {
  EXPECT_EQ(parse_frame_kind("robust"), FrameKind::kRobust);
  EXPECT_EQ(parse_frame_kind("bbox"), FrameKind::kBbox);
  EXPECT_THROW(parse_frame_kind("quantile"), std::invalid_argument);
  EXPECT_THROW(measure_scene_frame({}), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
