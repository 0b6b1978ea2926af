// A -poc level comes with the counts that make it, in every door: the rays a
// viewpoint sent are its hits, its rays through openings, its occlusion rays
// and its rays outside the view, and the level is the occlusion rays over the
// rays inside the view. The sentence the report carries (`level_counts`, the
// one the CLI prints and the viewer shows) names the same numbers.

#include <gtest/gtest.h>

#include <string>

#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/in_memory_jobs.hpp"
#include "support/mesh_truth.hpp"

namespace occlusion {
namespace {

using testing::furnished_room;
using testing::SampledCloud;
using testing::station_scan;

void expect_adds_up(const Json::Value& counts) {
  const auto n = [&](const char* key) { return counts[key].asUInt64(); };
  EXPECT_EQ(n("hits") + n("through_openings") + n("occlusion_rays") + n("outside_view_rays"),
            n("rays"));
  EXPECT_EQ(n("rays_in_view"), n("rays") - n("outside_view_rays"));
  ASSERT_GT(n("rays_in_view"), 0u);
  EXPECT_DOUBLE_EQ(
      counts["occlusion_level"].asDouble(),
      static_cast<double>(n("occlusion_rays")) / static_cast<double>(n("rays_in_view")));
  const std::string text = counts["level_counts"].asString();
  for (const char* key : {"occlusion_rays", "rays_in_view", "hits", "through_openings"}) {
    EXPECT_NE(text.find(std::to_string(n(key))), std::string::npos) << key << ": " << text;
  }
}

TEST(LevelCounts, AStationsLevelCountsOnlyTheRaysInsideItsWindowAndSaysWhy) {
  const Eigen::Vector3d station(1.0, 1.0, 1.6);
  SampledCloud scan = station_scan(furnished_room(), station, 0.04, 0.01);
  // As an E57 scan records it: the pose and the grid (its window is measured from them).
  Station recorded{"station 1", {}};
  recorded.frame.origin = station;
  recorded.frame.width = 158;
  recorded.frame.height = 297;
  scan.cloud.stations = {recorded};
  CloudOcclusionRequest request;
  request.path = "station";
  request.num_rays_per_vp = 20000;
  const Json::Value json = to_json(cloud_occlusion_in_memory(scan.cloud, request));
  // The scanner never looked at the poles above and below 85 degrees.
  ASSERT_GT(json["outside_view_rays"].asUInt64(), 0u);
  expect_adds_up(json);
  ASSERT_EQ(json["viewpoints"].size(), 1u);
  expect_adds_up(json["viewpoints"][0]);
  const std::string text = json["level_counts"].asString();
  EXPECT_NE(text.find(std::to_string(json["outside_view_rays"].asUInt64()) + " of the " +
                      std::to_string(json["rays"].asUInt64()) + " rays are outside the field " +
                      "of view of station 'station 1'"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("never measured, not counted"), std::string::npos) << text;
}

TEST(LevelCounts, WithoutAFieldOfViewEveryRayCounts) {
  SampledCloud room = testing::sample_room(furnished_room(true), 200.0, 7);
  CloudOcclusionRequest request;
  request.path = "room";
  request.num_rays_per_vp = 5000;
  request.viewpoints = ViewpointChoice::from_grid(2);
  const Json::Value json = to_json(cloud_occlusion_in_memory(room.cloud, request));
  EXPECT_EQ(json["outside_view_rays"].asUInt64(), 0u);
  EXPECT_GT(json["occlusion_rays"].asUInt64(), 0u);  // the window lets rays out
  expect_adds_up(json);
  for (const Json::Value& viewpoint : json["viewpoints"]) expect_adds_up(viewpoint);
  EXPECT_EQ(json["level_counts"].asString().find("view"), std::string::npos)
      << json["level_counts"].asString();
}

}  // namespace
}  // namespace occlusion
