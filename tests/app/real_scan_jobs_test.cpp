// Issue 12 items 1-4 at the job level: automatic radius, robust frame, up
// axis and single-view frames, on scenes whose answer is known.
#include <gtest/gtest.h>

#include "io/scratch_directory.hpp"
#include "occlusion/analysis/scene_frame.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/default_viewpoints.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/in_memory_jobs.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "support/cloud_scenes.hpp"
#include "support/kinect_frame.hpp"

namespace occlusion {
namespace {

using testing::ScratchDirectory;

ViewpointChoice::Resolved at_sensor() {
  ViewpointChoice::Resolved sensor;
  sensor.positions = {Eigen::Vector3d::Zero()};
  sensor.names = {"sensor"};
  return sensor;
}

bool any_warning_has(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& warning : warnings) {
    if (warning.find(text) != std::string::npos) return true;
  }
  return false;
}

// The room [0, 4] x [0, 3] x [0, 2.5] every 5 cm plus 200 stray points over a
// 30 x 14 x 6 m box around it.
PointCloud room_with_strays() {
  PointCloud cloud;
  testing::add_box_grid(cloud, 80, 60, 50, 0.05);
  Rng rng(3);
  for (int k = 0; k < 200; ++k) {
    cloud.positions.emplace_back(static_cast<float>(-13.0 + 30.0 * rng.uniform()),
                                 static_cast<float>(-5.5 + 14.0 * rng.uniform()),
                                 static_cast<float>(-2.0 + 6.0 * rng.uniform()));
  }
  return cloud;
}

TEST(RealScanJobs, ScanOfAKinectFrameFromItsSensorKeepsItWithDefaults) {
  const PointCloud frame = testing::kinect_like_frame(320, 240, 57.0, 0.002);
  ScanRequest request;
  request.path = "kinect frame";
  const ScanReport report = run_scan_on(frame, at_sensor(), request);
  EXPECT_GE(report.result.visible_fraction, 0.99);
  const PointModelReport& model = report.point_model;
  EXPECT_EQ(model.primitive, "disc");
  EXPECT_TRUE(model.radius.automatic);
  ASSERT_TRUE(model.surfels);
  EXPECT_GT(model.surfels->oriented, frame.size() * 9 / 10);
  EXPECT_DOUBLE_EQ(model.radius.radius, model.surfels->radius_median);
  EXPECT_TRUE(report.warnings.empty());
  const Json::Value json = to_json(report);
  EXPECT_DOUBLE_EQ(json["parameters"]["point_radius"].asDouble(), model.radius.radius);
  EXPECT_EQ(json["parameters"]["self_tolerance"].asString(), "auto");  // per point and ray
  EXPECT_EQ(json["point_model"]["primitive"].asString(), "disc");
  EXPECT_EQ(json["point_model"]["discs"].asUInt64(), model.surfels->oriented);
  EXPECT_DOUBLE_EQ(json["point_spacing"]["spacing"].asDouble(), model.radius.spacing.spacing);

  // The thesis' spheres, auto: a quarter of the spacing, tolerance 2 x radius.
  request.primitive = "sphere";
  const ScanReport spheres = run_scan_on(frame, at_sensor(), request);
  EXPECT_GE(spheres.result.visible_fraction, 0.99);
  EXPECT_DOUBLE_EQ(spheres.point_model.radius.radius,
                   kScanRadiusPerSpacing * spheres.point_model.radius.spacing.spacing);
  EXPECT_DOUBLE_EQ(to_json(spheres)["parameters"]["self_tolerance"].asDouble(),
                   2.0 * spheres.point_model.radius.radius);

  // Spheres of several spacings hide points: the warning says so.
  request.point_radius = 0.03;
  const ScanReport fixed = run_scan_on(frame, at_sensor(), request);
  EXPECT_LT(fixed.result.visible_fraction, 0.99);
  EXPECT_TRUE(any_warning_has(fixed.warnings, "visible fraction is too low"));
  request.point_radius = 1e-5;
  EXPECT_TRUE(any_warning_has(run_scan_on(frame, at_sensor(), request).warnings, "is too high"));
}

TEST(RealScanJobs, OcclusionOfAFrameIsTakenOverItsFieldOfView) {
  const PointCloud frame = testing::kinect_like_frame(160, 120, 57.0);
  CloudOcclusionRequest request;
  request.path = "kinect frame";
  request.num_rays_per_vp = 4000;
  request.point_radius = 0.05;  // closes every gap between pixels of this frame
  const CloudOcclusionReport report = run_cloud_occlusion_on(frame, at_sensor(), {}, request);
  ASSERT_TRUE(report.field_of_view);
  // 57 x 44.6 degrees is about 7 % of the sphere: the rest is outside the view.
  EXPECT_GT(report.result.outside_view_rays, 3600u);
  EXPECT_EQ(report.result.occlusion_rays, 0u);
  EXPECT_EQ(report.result.occlusion_level, 0.0);
  const Json::Value json = to_json(report);
  EXPECT_EQ(json["field_of_view"]["source"].asString(), "organised frame 160 x 120");
  EXPECT_NEAR(json["field_of_view"]["horizontal_degrees"].asDouble(), 57.0, 1e-3);
  EXPECT_EQ(json["outside_view_rays"].asUInt64(), report.result.outside_view_rays);

  // The same points, unorganised and without a pose: every ray counts.
  PointCloud unorganised = frame;
  unorganised.sensor = SensorFrame{};
  unorganised.pixels.clear();
  const CloudOcclusionReport all = run_cloud_occlusion_on(unorganised, at_sensor(), {}, request);
  EXPECT_FALSE(all.field_of_view);
  EXPECT_EQ(all.result.outside_view_rays, 0u);
  // The rays outside the view become occlusion rays, but for the few that
  // graze the spheres of the frame's border points.
  EXPECT_LE(all.result.occlusion_rays, report.result.outside_view_rays);
  EXPECT_GT(all.result.occlusion_rays, report.result.outside_view_rays * 99 / 100);
  // ... unless a field of view is given.
  request.field_of_view = {57.0, 44.6};
  const CloudOcclusionReport given = run_cloud_occlusion_on(unorganised, at_sensor(), {}, request);
  ASSERT_TRUE(given.field_of_view);
  EXPECT_EQ(to_json(given)["field_of_view"]["source"].asString(), "field_of_view setting");
  EXPECT_LT(given.result.occlusion_level, 0.01);
}

TEST(RealScanJobs, PatternsLandInTheRoomOfAScanWithStrayPoints) {
  const ScratchDirectory dir;
  CloudOcclusionRequest request;
  request.path = dir.file("room.ply");
  write_cloud(request.path, room_with_strays());
  request.viewpoints = ViewpointChoice::from_pattern(7);
  request.num_rays_per_vp = 2000;
  request.point_radius = 0.05;  // the room's spacing: its surfaces are closed
  const CloudOcclusionReport robust = run_cloud_occlusion(request);
  Box room;
  room.hi = Eigen::Vector3d(4.0, 3.0, 2.5);
  for (const auto& view : robust.result.viewpoints) {
    EXPECT_TRUE(room.contains(view.position)) << view.position.transpose();
  }
  EXPECT_FALSE(any_warning_has(robust.warnings, "outside the occupied space"));
  // A closed room seen from inside: no ray escapes.
  EXPECT_EQ(robust.result.occlusion_rays, 0u);
  const Json::Value json = to_json(robust);
  EXPECT_EQ(json["frame"]["frame"].asString(), "robust");
  EXPECT_LT(json["frame"]["bbox"]["min"][0].asDouble(), -10.0);
  EXPECT_DOUBLE_EQ(json["frame"]["robust"]["min"][0].asDouble(), 0.0);
  EXPECT_DOUBLE_EQ(json["frame"]["robust"]["max"][2].asDouble(), 2.5);
  EXPECT_EQ(json["viewpoints"].size(), 3u);

  // On the raw bounding box two of the three leave the room, and are warned about.
  request.frame = "bbox";
  const CloudOcclusionReport raw = run_cloud_occlusion(request);
  int outside = 0;
  for (const auto& view : raw.result.viewpoints) outside += room.contains(view.position) ? 0 : 1;
  EXPECT_GE(outside, 2);
  int warned = 0;
  for (const auto& warning : raw.warnings) {
    warned += warning.find("outside the occupied space") != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(warned, outside);
  EXPECT_GT(raw.result.occlusion_level, 0.3);
}

TEST(RealScanJobs, GridFollowsUpAndWarnsWhenTheDataDisagree) {
  const ScratchDirectory dir;
  PointCloud camera;  // the room in a camera frame: y down, z forward
  testing::add_box_grid(camera, 80, 60, 50, 0.05);
  for (auto& p : camera.positions) p = Eigen::Vector3f(p.x(), -p.z(), p.y());
  ScanRequest request;
  request.path = dir.file("camera.ply");
  write_cloud(request.path, camera);
  request.viewpoints = ViewpointChoice::from_grid(4);
  request.point_radius = 0.025;
  request.up = "-y";
  const ScanReport right = run_scan(request);
  for (const auto& p : right.viewpoint_positions) EXPECT_DOUBLE_EQ(p.y(), -1.25);
  EXPECT_FALSE(any_warning_has(right.warnings, "up is"));
  EXPECT_EQ(to_json(right)["frame"]["up"].asString(), "-y");

  request.up = "+z";  // the default, wrong for this frame
  const ScanReport wrong = run_scan(request);
  for (const auto& p : wrong.viewpoint_positions) EXPECT_DOUBLE_EQ(p.z(), 1.5);
  EXPECT_TRUE(any_warning_has(wrong.warnings,
                              "up is +z, but the largest flat structure is "
                              "perpendicular to y"));
}

// The defaults the server sends the viewer are -poc's grid, with the up
// warning the CLI gives (the viewer had shown neither, issue 41).
TEST(RealScanJobs, TheDefaultsSentToTheViewerCarryTheJobsWarnings) {
  PointCloud camera;  // the room in a camera frame: y down, z forward
  testing::add_box_grid(camera, 80, 60, 50, 0.05);
  for (auto& p : camera.positions) p = Eigen::Vector3f(p.x(), -p.z(), p.y());
  const Json::Value defaults = default_viewpoints_json(camera);
  const Json::Value& sent = defaults["cloud_occlusion"];
  CloudOcclusionRequest request;
  request.path = "camera";
  request.primitive = "sphere";
  request.point_radius = 0.025;
  request.num_rays_per_vp = 500;
  const CloudOcclusionReport report = cloud_occlusion_in_memory(camera, request);
  const Json::Value poc = to_json(report);
  EXPECT_EQ(sent["viewpoint_source"].asString(), "num_vp 9");
  EXPECT_EQ(sent["viewpoint_source"], poc["viewpoint_source"]);
  ASSERT_EQ(sent["viewpoints"].size(), poc["viewpoints"].size());
  for (Json::ArrayIndex v = 0; v < sent["viewpoints"].size(); ++v) {
    EXPECT_EQ(sent["viewpoints"][v]["position"], poc["viewpoints"][v]["position"]);
  }
  ASSERT_EQ(sent["warnings"].size(), 1u);
  EXPECT_NE(sent["warnings"][0].asString().find("up is +z"), std::string::npos);
  EXPECT_TRUE(any_warning_has(report.warnings, sent["warnings"][0].asString()));
  EXPECT_EQ(defaults["scan"]["viewpoint_source"].asString(), "pattern 7");
}

TEST(RealScanJobs, RefusesUnknownFrameUpAndFieldOfView) {
  ScanRequest scan;
  scan.path = "x.ply";
  scan.frame = "box";
  EXPECT_THROW(validate(scan), UsageError);
  scan.frame = "bbox";
  scan.up = "down";
  EXPECT_THROW(validate(scan), UsageError);
  scan.up = "-z";
  scan.point_radius = 0.0;
  EXPECT_THROW(validate(scan), UsageError);
  scan.point_radius = -1.0;
  EXPECT_THROW(validate(scan), UsageError);
  CloudOcclusionRequest poc;
  poc.path = "x.ply";
  poc.field_of_view = {57.0};
  EXPECT_THROW(validate(poc), UsageError);
  poc.field_of_view = {57.0, 190.0};
  EXPECT_THROW(validate(poc), UsageError);
  poc.field_of_view = {57.0, 43.0};
  EXPECT_NO_THROW(validate(poc));
}

}  // namespace
}  // namespace occlusion
