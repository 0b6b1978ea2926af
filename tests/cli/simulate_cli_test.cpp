// simulate end to end: the sample room scanned by the virtual laser scanner
// and depth camera, what it writes read back as any cloud (stations, labels,
// truth), its counts adding up, and its refusals.

#include <gtest/gtest.h>

#include <cmath>

#include "occlusion/io/cloud_io.hpp"
#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kRoom = "'" + kSource + "/files/sample_room.obj'";
// A coarse laser keeps the test small: 1 degree steps, 360 x 151 beams.
const std::string kCoarse = " --azimuth-step 1 --elevation-step 1";

std::size_t sum_of(const Json::Value& counts) {
  return counts["points"].asUInt64() + counts["no_return"].asUInt64() +
         counts["out_of_range"].asUInt64() + counts["beyond_max_incidence"].asUInt64();
}

TEST(SimulateCli, ALaserScanIsWrittenWithItsStationsLabelsAndTruth) {
  const TempDir dir;
  const Json::Value report =
      run_json("simulate " + kRoom + kCoarse +
               " --station 2,2,1.5 --station 5,3,1.5 --truth --out '" + dir.path() + "'");
  EXPECT_EQ(report["job"].asString(), "simulate");
  EXPECT_EQ(report["beams"]["beams"].asUInt64(), 2u * 360u * 151u);
  EXPECT_EQ(sum_of(report["beams"]), report["beams"]["beams"].asUInt64());
  ASSERT_EQ(report["stations"].size(), 2u);
  std::size_t per_station = 0;
  for (const auto& station : report["stations"]) {
    EXPECT_EQ(sum_of(station["beams"]), station["beams"]["beams"].asUInt64());
    per_station += station["beams"]["points"].asUInt64();
  }
  EXPECT_EQ(per_station, report["points"].asUInt64());

  CloudReadReport read;
  const PointCloud cloud = read_cloud(dir.file("sample_room.sim.ply"), {}, &read);
  ASSERT_EQ(cloud.size(), report["points"].asUInt64());
  ASSERT_EQ(cloud.stations.size(), 2u);
  EXPECT_NEAR(cloud.stations[1].frame.origin.x(), 5.0, 1e-9);
  EXPECT_EQ(cloud.stations[0].frame.width, 360u);  // the grid: columns x rows
  EXPECT_EQ(cloud.stations[0].frame.height, 151u);
  ASSERT_TRUE(cloud.has_station_ids() && cloud.has_labels() && cloud.has_instances());
  // Classes from the groups, less their numbers: bookcase_1 .. bookcase_3 are one class.
  std::size_t bookcases = 0;
  for (const auto& name : cloud.class_names) bookcases += name == "bookcase" ? 1 : 0;
  EXPECT_EQ(bookcases, 1u);
  // Every point lies within a few sigma (3 mm) of its true surface point.
  ASSERT_EQ(read.extra_fields.size(), 7u);  // true_x .. true_normal_z, face
  EXPECT_EQ(read.extra_fields[0].name, "true_x");
  double worst = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d truth(read.extra_fields[0].values[i], read.extra_fields[1].values[i],
                                read.extra_fields[2].values[i]);
    worst = std::max(worst, (cloud.positions[i].cast<double>() - truth).norm());
  }
  EXPECT_GT(worst, 0.003);  // noise is on by default
  EXPECT_LT(worst, 0.003 * 6);
}

TEST(SimulateCli, TheWrittenScanIsSeenFromItsOwnStationsByDefault) {
  const TempDir dir;
  run_json("simulate " + kRoom + kCoarse + " --station 2,2,1.5 --noise false --out '" + dir.path() +
           "'");
  const Json::Value scan = run_json("-fscan '" + dir.file("sample_room.sim.ply") + "'");
  EXPECT_EQ(scan["viewpoint_source"].asString(), "stations of the file");
  ASSERT_EQ(scan["viewpoints"].size(), 1u);
  EXPECT_EQ(scan["viewpoints"][0]["name"].asString(), "station_1");
  EXPECT_NEAR(scan["viewpoints"][0]["position"][0].asDouble(), 2.0, 1e-9);
}

TEST(SimulateCli, ADepthCameraLooksWhereItIsTold) {
  const Json::Value report =
      run_json("simulate " + kRoom +
               " --sensor camera --width 160 --height 120 --fx 145 --fy 145 --station 1,1,1.2 "
               "--look-at 5,4,1");
  EXPECT_EQ(report["beams"]["beams"].asUInt64(), 160u * 120u);
  EXPECT_EQ(sum_of(report["beams"]), 160u * 120u);
  EXPECT_GT(report["points"].asUInt64(), 160u * 120u / 2);
  EXPECT_DOUBLE_EQ(report["parameters"]["cx"].asDouble(), 79.5);  // auto: the image's centre
  EXPECT_FALSE(report["parameters"].isMember("azimuth_step"));    // the laser's keys did nothing
}

TEST(SimulateCli, ACameraWritesTheDepthFrameItsReaderReadsBack) {
  const TempDir dir;
  const Json::Value report =
      run_json("simulate " + kRoom +
               " --sensor camera --width 160 --height 120 --fx 145 --fy 145 --station 1,1,1.2 "
               "--look-at 5,4,1 --out '" +
               dir.path() + "'");
  ASSERT_EQ(report["outputs"].size(), 4u);
  const PointCloud scan = read_cloud(dir.file("sample_room.sim.ply"));
  const PointCloud frame = read_cloud(dir.file("sample_room.sim.frame.json"));
  ASSERT_EQ(frame.size(), scan.size());
  ASSERT_TRUE(frame.sensor.organised());
  EXPECT_EQ(frame.sensor.width, 160u);
  EXPECT_NEAR(frame.sensor.origin.z(), 1.2, 1e-9);
  // The frame's points are the scan's, pixel by pixel, to the PNG's 0.2 mm.
  double worst = 0.0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    worst = std::max(worst, (frame.positions[i] - scan.positions[i]).cast<double>().norm());
  }
  EXPECT_LT(worst, 2.5e-4);
  // Seen from its own camera by default, as any depth frame.
  const Json::Value seen = run_json("-fscan '" + dir.file("sample_room.sim.frame.json") + "'");
  EXPECT_EQ(seen["viewpoints"][0]["name"].asString(), "station_1");
}

TEST(SimulateCli, RequestsNoSensorCanMakeAreRefusedNamingTheKey) {
  const auto camera = run_cli("simulate " + kRoom + " --sensor camera --station 1,1,1");
  EXPECT_EQ(camera.exit_code, 2);
  EXPECT_NE(camera.err.find("look_at"), std::string::npos) << camera.err;
  const auto laser_look = run_cli("simulate " + kRoom + " --look-at 1,1,1");
  EXPECT_EQ(laser_look.exit_code, 2);
  EXPECT_NE(laser_look.err.find("camera only"), std::string::npos) << laser_look.err;
  // 1e-5 degree steps: 3.6e7 x 1.5e7 beams, refused before anything is traced.
  const auto fine = run_cli("simulate " + kRoom + " --azimuth-step 1e-5 --elevation-step 1e-5");
  EXPECT_EQ(fine.exit_code, 2);
  EXPECT_NE(fine.err.find("beams"), std::string::npos) << fine.err;
  const auto window = run_cli("simulate " + kRoom + " --elevation-min 10 --elevation-max 5");
  EXPECT_EQ(window.exit_code, 2);
  EXPECT_NE(window.err.find("elevation"), std::string::npos) << window.err;
}

TEST(SimulateCli, TheSameSeedWritesTheSameCloud) {
  const TempDir a, b;
  run_json("simulate " + kRoom + kCoarse + " --seed 7 --threads 1 --out '" + a.path() + "'");
  run_json("simulate " + kRoom + kCoarse + " --seed 7 --threads 2 --out '" + b.path() + "'");
  EXPECT_EQ(testing::read_text(a.file("sample_room.sim.ply")),
            testing::read_text(b.file("sample_room.sim.ply")));
}

}  // namespace
}  // namespace occlusion
