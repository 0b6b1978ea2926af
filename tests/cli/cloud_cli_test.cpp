// -recon, -poc and -fscan end to end on the synthetic S3DIS office
// (files/s3dis_synthetic) and the real scan room_scan1.pcd.

#include <gtest/gtest.h>
#include <json/reader.h>

#include <sstream>

#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::CliRun;
using testing::parse_json;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kRoom = "'" + kSource + "/files/s3dis_synthetic/Area_1/office_1'";
const std::string kArea = "'" + kSource + "/files/s3dis_synthetic/Area_1'";
const std::string kOpenings = "'" + kSource + "/files/s3dis_synthetic/openings.txt'";
const std::string kRealScan = "'" + kSource + "/files/pcl/room_scan1.pcd'";
// The sample office's surfaces are closed by the default model (discs sized
// from their neighbours); spheres needed --point-radius 0.06 for it.
const std::string kClosedSurfaces = "";

std::size_t class_points(const Json::Value& classes, const std::string& name,
                         const char* field = "points") {
  for (const auto& c : classes) {
    if (c["name"].asString() == name) return c[field].asUInt64();
  }
  ADD_FAILURE() << "no class " << name;
  return 0;
}

TEST(CloudCli, ReconstructRoomAndArea) {
  const TempDir dir;
  const Json::Value room = run_json("-recon " + kRoom + " --out '" + dir.path() + "'");
  EXPECT_EQ(room["job"].asString(), "reconstruct");
  EXPECT_EQ(room["classes"].size(), 13u);
  EXPECT_GT(class_points(room["classes"], "window"), 0u);
  EXPECT_GT(class_points(room["classes"], "door"), 0u);
  EXPECT_EQ(class_points(room["classes"], "chair", "instances"), 4u);
  std::size_t total = 0;
  for (const auto& c : room["classes"]) total += c["points"].asUInt64();
  EXPECT_EQ(total, room["points"].asUInt64());
  EXPECT_FALSE(testing::read_text(dir.file("office_1.ply")).empty());

  const Json::Value area = run_json("-recon " + kArea + " --format pcd --out '" + dir.path() + "'");
  ASSERT_EQ(area["rooms"].size(), 1u);
  EXPECT_EQ(area["points"].asUInt64(), room["points"].asUInt64());
  EXPECT_EQ(testing::read_text(dir.file("Area_1.pcd")).rfind("# .PCD", 0), 0u);
}

TEST(CloudCli, OpeningsTurnEscapesIntoExits) {
  const std::string base = "-poc " + kRoom + kClosedSurfaces + " --num-rays-per-vp 4000";
  const Json::Value open = run_json(base);
  const Json::Value covered = run_json(base + " --polygon-path " + kOpenings);
  EXPECT_EQ(open["viewpoints"].size(), 9u);  // the default num_vp
  EXPECT_EQ(open["rays"].asUInt64(), 9u * 4000u);
  EXPECT_EQ(open["through_openings"].asUInt64(), 0u);
  EXPECT_EQ(covered["openings"].asUInt64(), 2u);
  // The window and door are the room's only holes: covering them turns
  // (almost) every escaping ray into an exit.
  EXPECT_GT(open["occlusion_rays"].asUInt64(), 200u);
  EXPECT_GT(covered["through_openings"].asUInt64(), 9 * open["occlusion_rays"].asUInt64() / 10);
  EXPECT_LT(covered["occlusion_level"].asDouble(), open["occlusion_level"].asDouble() / 10);
  // Same seed, same rays: hits do not change.
  EXPECT_EQ(covered["hits"].asUInt64() + covered["through_openings"].asUInt64() +
                covered["occlusion_rays"].asUInt64(),
            covered["rays"].asUInt64());
}

TEST(CloudCli, ExteriorVariantAndRatio) {
  const Json::Value json =
      run_json("-poc " + kRoom + kClosedSurfaces +
               " --num-rays-per-vp 2000 --exterior --polygon-path " + kOpenings);
  ASSERT_TRUE(json.isMember("exterior"));
  const Json::Value& exterior = json["exterior"];
  const double interior = static_cast<double>(exterior["interior_points"].asUInt64());
  const double outside = static_cast<double>(exterior["exterior_points"].asUInt64());
  EXPECT_GT(interior, 0.0);
  EXPECT_NEAR(json["interior_exterior_ratio"].asDouble(), interior / outside, 1e-12);
  EXPECT_EQ(exterior["blocking_points"].asUInt64(), exterior["exterior_points"].asUInt64());
  // Without the furniture, rays reach the walls where the furniture hid them:
  // the exterior structure has holes there.
  EXPECT_GT(exterior["occlusion_level"].asDouble(), json["occlusion_level"].asDouble());
}

TEST(CloudCli, ScanWritesSeenAndFullClouds) {
  const TempDir dir;
  // The radius the point-radius default was before it became auto, as spheres:
  // discs are re-estimated on the scanned cloud, whose new edges change a few.
  const std::string radius = " --primitive sphere --point-radius 0.01";
  const Json::Value json =
      run_json("-fscan " + kRoom + radius + " --pattern 1 --out '" + dir.path() + "'");
  const double fraction = json["visible_fraction"].asDouble();
  EXPECT_GT(fraction, 0.3);
  EXPECT_LT(fraction, 1.0);
  EXPECT_EQ(json["viewpoints"].size(), 1u);
  EXPECT_EQ(json["classes"].size(), 13u);
  EXPECT_NE(testing::read_text(dir.file("office_1.scan_full.ply")).find("visible_count"),
            std::string::npos);
  // The scanned cloud has only points the viewpoint saw, and fewer blockers
  // than the full one: scanned again from the same viewpoint, all are seen.
  const Json::Value again =
      run_json("-fscan '" + dir.file("office_1.scan.ply") + "'" + radius + " --viewpoint " +
               json["viewpoints"][0]["position"][0].asString() + "," +
               json["viewpoints"][0]["position"][1].asString() + "," +
               json["viewpoints"][0]["position"][2].asString());
  EXPECT_EQ(again["points"].asUInt64(), json["visible_points"].asUInt64());
  EXPECT_EQ(again["visible_fraction"].asDouble(), 1.0);
}

TEST(CloudCli, ExampleConfigRunsEveryCloudJob) {
  const std::string config = " --config '" + kSource + "/config/example.json'";
  const Json::Value poc = run_json("-poc" + config + " --num-rays-per-vp 1000");
  EXPECT_EQ(poc["viewpoints"].size(), 9u);
  EXPECT_EQ(poc["openings"].asUInt64(), 2u);
  EXPECT_TRUE(poc.isMember("exterior"));
  const Json::Value scan = run_json("-fscan" + config);
  EXPECT_GT(scan["visible_fraction"].asDouble(), 0.0);
  const TempDir dir;
  const Json::Value recon = run_json("-recon" + config + " --out '" + dir.path() + "'");
  EXPECT_EQ(recon["rooms"].size(), 1u);
}

// The real Kinect frame (issue 12.2 and 12.4): from its own sensor, with
// the default (automatic) radius, the scan keeps every point, and occlusion
// is taken over the sensor's field of view.
TEST(CloudCli, KinectFrameFromItsSensor) {
  const std::string frame = "'" + kSource + "/files/pcl/mosd_learn25.pcd' --viewpoint 0,0,0";
  const Json::Value scan = run_json("-fscan " + frame);
  EXPECT_EQ(scan["points"].asUInt64(), 195021u);
  // Discs fitted to the frame's pixel grid: 99.3 % (the nearest points in
  // space kept 98.0 %; organised_frame_surfels_test.cpp); spheres of a
  // quarter spacing keep every point, and leak through every surface
  // (cloud_truth_test.cpp).
  EXPECT_GE(scan["visible_fraction"].asDouble(), 0.99);
  EXPECT_TRUE(scan["parameters"]["point_radius_auto"].asBool());
  EXPECT_EQ(scan["warnings"].size(), 0u);
  const Json::Value poc = run_json("-poc " + frame + " --num-rays-per-vp 3000");
  EXPECT_EQ(poc["field_of_view"]["source"].asString(), "organised frame 640 x 480");
  // A 57 x 41 degree view holds about 6 % of the directions.
  EXPECT_GT(poc["outside_view_rays"].asUInt64(), 2700u);
  EXPECT_EQ(poc["hits"].asUInt64() + poc["occlusion_rays"].asUInt64() +
                poc["outside_view_rays"].asUInt64(),
            3000u);
  EXPECT_LT(poc["occlusion_level"].asDouble(), 0.5);
  // The text says what the level counts, as the report does: the rays outside
  // the frame's view apart, and why.
  const std::string counts = poc["level_counts"].asString();
  EXPECT_NE(counts.find(std::to_string(poc["outside_view_rays"].asUInt64()) +
                        " of the 3000 rays are outside the frame's"),
            std::string::npos)
      << counts;
  const CliRun text = run_cli("-poc " + frame + " --num-rays-per-vp 3000 -q");
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("occlusion level  " + counts + "\n"), std::string::npos) << text.out;
}

TEST(CloudCli, RealScanRuns) {
  const Json::Value json = run_json("-poc " + kRealScan + " --num-rays-per-vp 2000 --num-vp 4");
  EXPECT_EQ(json["points"].asUInt64(), 112586u);
  EXPECT_GE(json["occlusion_level"].asDouble(), 0.0);
  EXPECT_LE(json["occlusion_level"].asDouble(), 1.0);
}

TEST(CloudCli, Errors) {
  EXPECT_EQ(run_cli("-poc /nonexistent.pcd").exit_code, 3);
  EXPECT_EQ(run_cli("-poc " + kRealScan + " --exterior -q").exit_code, 2);  // no labels
  EXPECT_EQ(run_cli("-poc " + kRoom + " --sampling sobol").exit_code, 2);
  EXPECT_EQ(run_cli("-poc " + kRoom + " --exterior-classes wall,lava -q").exit_code, 2);
  EXPECT_EQ(run_cli("-poc " + kRoom + " --point-radius 0").exit_code, 2);
  EXPECT_EQ(run_cli("-fscan " + kRoom + " --format obj").exit_code, 2);
  const CliRun not_s3dis = run_cli("-recon '" + kSource + "/files/cornell_box' -q");
  EXPECT_EQ(not_s3dis.exit_code, 3);  // a folder, but no S3DIS room in it
  EXPECT_NE(not_s3dis.err.find("cornell_box"), std::string::npos) << not_s3dis.err;
  const TempDir dir;
  dir.write("two_points.txt", "0 0 0\n1 0 0\n");
  const CliRun bad_polygon =
      run_cli("-poc " + kRoom + " -q --polygon-path '" + dir.file("two_points.txt") + "'");
  EXPECT_EQ(bad_polygon.exit_code, 3);
  EXPECT_NE(bad_polygon.err.find("two_points.txt"), std::string::npos) << bad_polygon.err;
}

}  // namespace
}  // namespace occlusion
