#include "occlusion/analysis/viewpoints.hpp"

#include <gtest/gtest.h>

namespace occlusion {
namespace {

const Eigen::Vector3d kLo(0, 0, 0), kHi(4, 8, 2);
const Eigen::Vector3d kCentre(2, 4, 1), kMaxMid(3, 6, 1.5), kMinMid(1, 2, 0.5);

TEST(Viewpoints, PatternsAreTheDocumentedSubsets) {
  using V = std::vector<Eigen::Vector3d>;
  EXPECT_EQ(pattern_viewpoints(1, kLo, kHi), V({kCentre}));
  EXPECT_EQ(pattern_viewpoints(2, kLo, kHi), V({kMaxMid}));
  EXPECT_EQ(pattern_viewpoints(3, kLo, kHi), V({kMinMid}));
  EXPECT_EQ(pattern_viewpoints(4, kLo, kHi), V({kCentre, kMaxMid}));
  EXPECT_EQ(pattern_viewpoints(5, kLo, kHi), V({kCentre, kMinMid}));
  EXPECT_EQ(pattern_viewpoints(6, kLo, kHi), V({kMaxMid, kMinMid}));
  EXPECT_EQ(pattern_viewpoints(7, kLo, kHi), V({kCentre, kMaxMid, kMinMid}));
  EXPECT_EQ(pattern_viewpoint_names(6), std::vector<std::string>({"max_mid", "min_mid"}));
}

TEST(Viewpoints, RejectsUnknownPatternsAndEmptyBoxes) {
  EXPECT_THROW(pattern_viewpoints(0, kLo, kHi), std::invalid_argument);
  EXPECT_THROW(pattern_viewpoints(8, kLo, kHi), std::invalid_argument);
  EXPECT_THROW(pattern_viewpoints(1, kHi, kLo), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
