// Clouds that record their scanner stations: the stations are -fscan's and
// -poc's default viewpoints (explicit keys still win), `scans` keeps the
// points of the stations it names, and min_range / max_range drop points by
// their range from their own station.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>

#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/default_viewpoints.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/in_memory_jobs.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/station_filter.hpp"

namespace occlusion {
namespace {

// A 4 x 4 m floor (z = 0) and a wall x = 4, points 10 cm apart, seen by two
// stations: "west" inside the room, "east" outside its box (behind the
// wall's side of it, where a scanner in the next room would stand).
PointCloud two_station_room() {
  PointCloud cloud;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      cloud.positions.emplace_back(0.1f * i, 0.1f * j, 0.0f);
      cloud.positions.emplace_back(4.0f, 0.1f * i, 0.075f * j);
    }
  }
  Station west{"west", {}}, east{"east", {}};
  west.frame.origin = Eigen::Vector3d(1.5, 2.0, 1.5);
  east.frame.origin = Eigen::Vector3d(6.0, 2.0, 1.5);
  cloud.stations = {west, east};
  for (const auto& p : cloud.positions) cloud.station_ids.push_back(p.x() > 3.5f ? 1 : 0);
  return cloud;
}

ScanRequest sphere_scan() {
  ScanRequest request;
  request.path = "room";
  request.primitive = "sphere";
  request.point_radius = 0.05;
  return request;
}

CloudOcclusionRequest sphere_poc() {
  CloudOcclusionRequest request;
  request.path = "room";
  request.primitive = "sphere";
  request.point_radius = 0.05;
  request.num_rays_per_vp = 1000;
  return request;
}

bool any_warning_has(const std::vector<std::string>& warnings, const std::string& part) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

template <class Request>
void set_key(const Keys<Request>& keys, Request& request, const std::string& name,
             const Json::Value& value) {
  for (const auto& k : keys) {
    if (k.info.name == name) return k.set(request, value);
  }
  FAIL() << "no key " << name;
}

TEST(StationViewpoints, DefaultViewpointsAreTheStations) {
  const PointCloud cloud = two_station_room();
  const ScanReport scan = scan_in_memory(cloud, sphere_scan());
  EXPECT_EQ(scan.viewpoint_names, (std::vector<std::string>{"west", "east"}));
  ASSERT_EQ(scan.viewpoint_positions.size(), 2u);
  EXPECT_EQ(scan.viewpoint_positions[1], Eigen::Vector3d(6.0, 2.0, 1.5));
  EXPECT_EQ(scan.viewpoint_source, "stations of the file");
  // "east" stands outside the box of the points, as scanners do: no warning.
  EXPECT_FALSE(any_warning_has(scan.warnings, "outside the occupied space"));
  const Json::Value json = to_json(scan);
  EXPECT_EQ(json["viewpoint_source"].asString(), "stations of the file");
  EXPECT_EQ(json["viewpoints"][1]["name"].asString(), "east");
  EXPECT_FALSE(json["parameters"].isMember("pattern")) << "the pattern was not used";

  const CloudOcclusionReport poc = cloud_occlusion_in_memory(cloud, sphere_poc());
  EXPECT_EQ(poc.viewpoint_names, (std::vector<std::string>{"west", "east"}));
  EXPECT_EQ(to_json(poc)["viewpoints"][0]["position"][0].asDouble(), 1.5);
  EXPECT_FALSE(to_json(poc)["parameters"].isMember("num_vp"));
}

// What the server sends with a loaded cloud, for the viewer's markers, is
// what the jobs take: the stations, and no warning at "east" though it stands
// outside the box (the viewer had warned there, issue 41).
TEST(StationViewpoints, TheDefaultsSentToTheViewerAreTheJobsViewpoints) {
  const PointCloud cloud = two_station_room();
  const Json::Value defaults = default_viewpoints_json(cloud);
  const Json::Value poc = to_json(cloud_occlusion_in_memory(cloud, sphere_poc()));
  const Json::Value scan = to_json(scan_in_memory(cloud, sphere_scan()));
  for (const auto& [job, report] : {std::pair{"cloud_occlusion", poc}, std::pair{"scan", scan}}) {
    const Json::Value& sent = defaults[job];
    EXPECT_EQ(sent["viewpoint_source"], report["viewpoint_source"]) << job;
    ASSERT_EQ(sent["viewpoints"].size(), report["viewpoints"].size()) << job;
    for (Json::ArrayIndex v = 0; v < sent["viewpoints"].size(); ++v) {
      EXPECT_EQ(sent["viewpoints"][v]["name"], report["viewpoints"][v]["name"]) << job;
      EXPECT_EQ(sent["viewpoints"][v]["position"], report["viewpoints"][v]["position"]) << job;
      EXPECT_FALSE(sent["viewpoints"][v]["outside_occupied_space"].asBool()) << job;
    }
    EXPECT_EQ(sent["warnings"].size(), 0u) << job;
  }
  EXPECT_GT(defaults["cloud_occlusion"]["viewpoints"][1]["position"][0].asDouble(),
            defaults["robust_box"]["max"][0].asDouble())
      << "east is outside the occupied space";
}

TEST(StationViewpoints, GivenViewpointKeysOverrideTheStations) {
  const PointCloud cloud = two_station_room();
  ScanRequest scan = sphere_scan();
  set_key(scan_keys(), scan, "pattern", 7);
  const ScanReport by_pattern = scan_in_memory(cloud, scan);
  EXPECT_EQ(by_pattern.viewpoint_source, "pattern 7");
  EXPECT_EQ(by_pattern.viewpoint_names.size(), 3u);
  EXPECT_EQ(to_json(by_pattern)["parameters"]["pattern"].asInt(), 7);

  CloudOcclusionRequest poc = sphere_poc();
  Json::Value points(Json::arrayValue);
  Json::Value point(Json::arrayValue);
  for (const double x : {2.0, 2.0, 1.0}) point.append(x);
  points.append(point);
  set_key(cloud_occlusion_keys(), poc, "viewpoints", points);
  const CloudOcclusionReport given = cloud_occlusion_in_memory(cloud, poc);
  EXPECT_EQ(given.viewpoint_source, "viewpoints");
  EXPECT_EQ(given.viewpoint_names, (std::vector<std::string>{"viewpoint_1"}));
}

TEST(StationViewpoints, WithoutStationsTheDefaultsStay) {
  PointCloud cloud = two_station_room();
  cloud.stations.clear();
  cloud.station_ids.clear();
  EXPECT_EQ(scan_in_memory(cloud, sphere_scan()).viewpoint_source, "pattern 7");
  EXPECT_EQ(cloud_occlusion_in_memory(cloud, sphere_poc()).viewpoint_source, "num_vp 9");
  // A single-view frame's sensor (a PCD VIEWPOINT) is its one station.
  cloud.sensor.origin = Eigen::Vector3d(1.0, 1.0, 1.0);
  const ScanReport sensor = scan_in_memory(cloud, sphere_scan());
  EXPECT_EQ(sensor.viewpoint_names, (std::vector<std::string>{"sensor"}));
  EXPECT_EQ(sensor.viewpoint_positions[0], Eigen::Vector3d(1.0, 1.0, 1.0));
}

TEST(StationViewpoints, ScansKeepThePointsOfTheStationsNamed) {
  PointCloud cloud = two_station_room();
  const std::size_t wall_points =
      static_cast<std::size_t>(std::count(cloud.station_ids.begin(), cloud.station_ids.end(), 1));
  const StationFilterReport report = apply_station_filter(cloud, {{"east"}, 0, 0}, "room.ply");
  EXPECT_EQ(report.other_scans, 41u * 41u + 41u * 41u - wall_points);
  EXPECT_EQ(cloud.size(), wall_points);
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_EQ(cloud.stations[0].name, "east");
  EXPECT_TRUE(std::all_of(cloud.station_ids.begin(), cloud.station_ids.end(),
                          [](std::int32_t id) { return id == 0; }));
  EXPECT_NO_THROW(cloud.validate());
  // Both named: nothing dropped.
  PointCloud both = two_station_room();
  EXPECT_EQ(apply_station_filter(both, {{"west", "east"}, 0, 0}, "room.ply").other_scans, 0u);
  EXPECT_EQ(both.size(), 2u * 41u * 41u);
}

TEST(StationViewpoints, ScansRefuseWhatTheFileDoesNotHold) {
  PointCloud cloud = two_station_room();
  try {
    apply_station_filter(cloud, {{"north"}, 0, 0}, "room.ply");
    FAIL() << "an unknown scan name was taken";
  } catch (const KeyError& e) {
    EXPECT_EQ(e.key, "scans");
    EXPECT_NE(std::string(e.what()).find("names no station of room.ply: 'north' (its stations: "
                                         "'west', 'east')"),
              std::string::npos)
        << e.what();
  }
  cloud.stations.clear();
  cloud.station_ids.clear();
  try {
    apply_station_filter(cloud, {{"west"}, 0, 0}, "plain.ply");
    FAIL() << "scans on a cloud without stations was taken";
  } catch (const KeyError& e) {
    EXPECT_NE(std::string(e.what()).find("plain.ply records no stations"), std::string::npos)
        << e.what();
  }
  PointCloud unknown_owner = two_station_room();
  unknown_owner.station_ids.clear();
  EXPECT_THROW(apply_station_filter(unknown_owner, {{"west"}, 0, 0}, "room.ply"), KeyError);
}

// Two stations 10 m apart; each point's range from its own station by hand.
PointCloud ranged_cloud() {
  PointCloud cloud;
  Station a{"a", {}}, b{"b", {}};
  b.frame.origin = Eigen::Vector3d(10, 0, 0);
  cloud.stations = {a, b};
  cloud.positions = {
      {0.3f, 0, 0},     // a: 0.3, the tripod
      {0, 2, 0},        // a: 2
      {10, 0.4f, 0},    // b: 0.4 (10 from a: kept if measured from a)
      {10, 0, 32.76f},  // b: 32.76, a no-return value
      {5, 0, 0},        // b: 5
      {0, 0, 32.76f},   // a: 32.76
  };
  cloud.station_ids = {0, 0, 1, 1, 1, 0};
  return cloud;
}

TEST(StationViewpoints, RangesAreMeasuredFromEachPointsOwnStation) {
  PointCloud cloud = ranged_cloud();
  const StationFilterReport report = apply_station_filter(cloud, {{}, 0.5, 32.7}, "r.ply");
  EXPECT_EQ(report.too_near, 2u);
  EXPECT_EQ(report.too_far, 2u);
  EXPECT_EQ(cloud.positions, (std::vector<Eigen::Vector3f>{{0, 2, 0}, {5, 0, 0}}));
  EXPECT_EQ(cloud.station_ids, (std::vector<std::int32_t>{0, 1}));
  // One station without ids: its range for every point.
  PointCloud single = ranged_cloud();
  single.stations.pop_back();
  single.station_ids.clear();
  const StationFilterReport one = apply_station_filter(single, {{}, 0.0, 10.0}, "r.ply");
  EXPECT_EQ(one.too_far, 3u);  // 10.008, 32.76 and 32.76 from a
  EXPECT_EQ(single.size(), 3u);
}

TEST(StationViewpoints, RangesNeedEachPointsStation) {
  PointCloud unknown_owner = ranged_cloud();
  unknown_owner.station_ids.clear();
  try {
    apply_station_filter(unknown_owner, {{}, 0.5, 0}, "r.ply");
    FAIL() << "ranges from unknown stations were taken";
  } catch (const KeyError& e) {
    EXPECT_EQ(e.key, "min_range");
    EXPECT_NE(std::string(e.what()).find("records 2 stations and not which one measured each"),
              std::string::npos)
        << e.what();
  }
  PointCloud none = ranged_cloud();
  none.stations.clear();
  none.station_ids.clear();
  try {
    apply_station_filter(none, {{}, 0, 30}, "plain.ply");
    FAIL() << "ranges without a station were taken";
  } catch (const KeyError& e) {
    EXPECT_EQ(e.key, "max_range");
    EXPECT_NE(std::string(e.what()).find("plain.ply records no station"), std::string::npos);
  }
  // Keys at 0 ask nothing of the cloud.
  EXPECT_EQ(apply_station_filter(none, {{}, 0, 0}, "plain.ply").too_far, 0u);
  EXPECT_EQ(none.size(), 6u);
  EXPECT_THROW(validate(StationFilter{{}, 5.0, 5.0}), KeyError);
}

TEST(StationViewpoints, JobsReportWhatTheFilterDropped) {
  ScanRequest request = sphere_scan();
  request.min_range = 0.5;
  request.max_range = 32.7;
  const ScanReport report = scan_in_memory(ranged_cloud(), request);
  EXPECT_EQ(report.result.visible_count.size(), 2u);
  const Json::Value json = to_json(report)["station_filter"];
  EXPECT_EQ(json["dropped_too_near"].asUInt64(), 2u);
  EXPECT_EQ(json["dropped_too_far"].asUInt64(), 2u);
  EXPECT_EQ(json["min_range"].asDouble(), 0.5);
}

}  // namespace
}  // namespace occlusion
