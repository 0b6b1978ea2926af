// One rule for positions over the protocol (docs/protocol.md, "Frames"): a
// cloud in UTM coordinates is streamed as float32 positions relative to its
// global shift, and every position in JSON, sent or received, is in the
// file's frame. Against a box room 500 km east and 5400 km north: the load's
// bounds and stations, the live station and -fscan at the same file-frame
// position, and the planes of extract_polygons.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "occlusion/io/cloud_io.hpp"
#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

const Eigen::Vector3d kShift(500000, 5400000, 0);

// A 4 x 3 x 2.5 box room on a 0.1 grid at kShift, with a station at
// (1.5, 1, 1.2) from its corner, written with coordinates in the file's frame.
PointCloud utm_room() {
  PointCloud cloud;
  cloud.shift = kShift;
  const double step = 0.1;
  const auto plane = [&](int axis, double at, double u1, double v1) {
    const int ua = axis == 0 ? 1 : 0, va = axis == 2 ? 1 : 2;
    for (double u = 0.05; u <= u1 + 1e-9; u += step) {
      for (double v = 0.05; v <= v1 + 1e-9; v += step) {
        Eigen::Vector3f p;
        p[axis] = static_cast<float>(at);
        p[ua] = static_cast<float>(u);
        p[va] = static_cast<float>(v);
        cloud.positions.push_back(p);
      }
    }
  };
  plane(2, 0.0, 3.95, 2.95);  // floor (x, y)
  plane(2, 2.5, 3.95, 2.95);  // ceiling
  plane(1, 0.0, 3.95, 2.45);  // walls (x, z)
  plane(1, 3.0, 3.95, 2.45);
  plane(0, 0.0, 2.95, 2.45);  // walls (y, z)
  plane(0, 4.0, 2.95, 2.45);
  cloud.stations = {{"tripod", {}}};
  cloud.stations[0].frame.origin = Eigen::Vector3d(1.5, 1, 1.2);  // local, as readers keep it
  return cloud;
}

// The same room as a mesh: 8 corners, 12 triangles facing in, written with
// its coordinates in the file's frame (0.25 and 0.5 are exact in float too).
void write_utm_room_mesh(const std::string& path) {
  std::ofstream obj(path);
  obj.precision(17);
  for (int corner = 0; corner < 8; ++corner) {
    obj << "v " << kShift.x() + 0.25 + ((corner & 1) ? 4.0 : 0.0) << ' '
        << kShift.y() + 0.5 + ((corner & 2) ? 3.0 : 0.0) << ' ' << ((corner & 4) ? 2.5 : 0.0)
        << '\n';
  }
  // Corner index = x + 2 y + 4 z, OBJ counts from 1.
  obj << "f 1 2 4\nf 1 4 3\nf 5 7 8\nf 5 8 6\n"   // floor, ceiling
      << "f 1 5 6\nf 1 6 2\nf 3 4 8\nf 3 8 7\n"   // y = 0, y = 3
      << "f 1 3 7\nf 1 7 5\nf 2 6 8\nf 2 8 4\n";  // x = 0, x = 4
}

class FileFrame : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server_ = new TestServer();
    write_cloud(server_->files().file("utm_room.ply"), utm_room());
    write_utm_room_mesh(server_->files().file("utm_room.obj"));
  }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }
  void SetUp() override { client_ = server_->connect(); }

  static TestServer* server_;
  std::unique_ptr<BlockingClient> client_;
};

TestServer* FileFrame::server_ = nullptr;

TEST_F(FileFrame, TheFileIsReadBackWithItsShift) {
  const PointCloud cloud = read_cloud(server_->files().file("utm_room.ply"));
  EXPECT_EQ(cloud.shift, kShift);
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_LT((cloud.stations[0].frame.origin - Eigen::Vector3d(1.5, 1, 1.2)).norm(), 1e-6);
}

TEST_F(FileFrame, LoadSendsLocalPositionsAndFileFramePositionsInJson) {
  const Reply reply = client_->request(1, "load", params(R"({"path": "utm_room.ply"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(result["shift"][axis].asDouble(), kShift[axis]);
  }
  // The frame: float32 positions in the local frame, within the room's 4 m.
  const auto positions = frame_values<float>(*find_frame(reply, "positions"));
  ASSERT_FALSE(positions.empty());
  for (const float v : positions) ASSERT_LE(std::abs(v), 4.01f);
  // JSON: the bounds and the station in the file's frame.
  const Json::Value& bounds = result["bounds"];
  EXPECT_NEAR(bounds["min"][0].asDouble(), 500000.0, 1e-6);
  EXPECT_NEAR(bounds["max"][0].asDouble(), 500004.0, 1e-6);
  EXPECT_NEAR(bounds["max"][1].asDouble(), 5400003.0, 1e-6);
  EXPECT_NEAR(bounds["max"][2].asDouble(), 2.5, 1e-6);
  ASSERT_EQ(result["stations"].size(), 1u) << result;
  const Json::Value& station = result["stations"][0]["position"];
  EXPECT_NEAR(station[0].asDouble(), 500001.5, 1e-6);
  EXPECT_NEAR(station[1].asDouble(), 5400001.0, 1e-6);
  EXPECT_NEAR(station[2].asDouble(), 1.2, 1e-6);
}

TEST_F(FileFrame, TheLiveStationAndScanAgreeAtTheSameFileFramePosition) {
  const Reply live =
      client_->request(2, "station_view",
                       params(R"({"path": "utm_room.ply", "position": [500001.5, 5400001, 1.2]})"));
  ASSERT_TRUE(live.ok()) << live.final;
  const Reply scan = client_->request(
      3, "scan",
      params(R"({"path": "utm_room.ply", "viewpoints": [[500001.5, 5400001, 1.2]], "out": ""})"));
  ASSERT_TRUE(scan.ok()) << scan.final;
  EXPECT_EQ(frame_values<std::uint16_t>(*find_frame(live, "visible_count")),
            frame_values<std::uint16_t>(*find_frame(scan, "visible_count")));
  // A convex room is seen almost whole from inside.
  EXPECT_GT(live.final["result"]["visible_fraction"].asDouble(), 0.95) << live.final;
  EXPECT_EQ(live.final["result"]["position"][0].asDouble(), 500001.5);
  // The CLI, given the same file-frame position, counts the same points.
  const Json::Value cli = run_cli_json("scan '" + server_->files().file("utm_room.ply") +
                                       "' --viewpoint 500001.5,5400001,1.2");
  ASSERT_TRUE(cli.isObject());
  EXPECT_EQ(cli["visible_points"], live.final["result"]["visible_points"]) << cli;
  // The local position, as the viewer sent it before, is another place
  // altogether: 5400 km away, too far to trace against 0.1 m points.
  const Reply local = client_->request(
      4, "station_view", params(R"({"path": "utm_room.ply", "position": [1.5, 1, 1.2]})"));
  EXPECT_EQ(local.error_code(), "invalid_request") << local.final;
}

TEST_F(FileFrame, ExtractPolygonsStreamsItsMeshInTheLocalFrame) {
  const Reply reply =
      client_->request(5, "extract_polygons", params(R"({"path": "utm_room.ply", "out": ""})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  ASSERT_GE(result["planes"].size(), 6u) << result;
  // The report: planes in the file's frame.
  for (const auto& plane : result["planes"]) {
    EXPECT_GT(plane["centroid"][0].asDouble(), 499999.0) << plane;
    EXPECT_GT(plane["centroid"][1].asDouble(), 5399999.0) << plane;
  }
  // The mesh frame: where the load's positions are, within the room.
  const auto vertices = frame_values<float>(*find_frame(reply, "positions"));
  ASSERT_FALSE(vertices.empty());
  for (std::size_t v = 0; v < vertices.size(); v += 3) {
    EXPECT_GT(vertices[v], -0.5f);
    EXPECT_LT(vertices[v], 4.5f);
    EXPECT_GT(vertices[v + 1], -0.5f);
    EXPECT_LT(vertices[v + 1], 3.5f);
  }
}

// A mesh is read in double, but drawn in float32 as a cloud is: in UTM
// coordinates it is streamed relative to the shift a cloud there would get
// (float32 is 0.5 m coarse at 5.4e6), and the live station on it takes
// file-frame positions as every job does.
TEST_F(FileFrame, AMeshFarOutIsStreamedRelativeToAShift) {
  const Reply reply = client_->request(6, "load", params(R"({"path": "utm_room.obj"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(result["shift"][axis].asDouble(), kShift[axis]) << result;
  }
  EXPECT_EQ(result["bounds"]["min"][0].asDouble(), 500000.25);
  EXPECT_EQ(result["bounds"]["max"][1].asDouble(), 5400003.5);
  const auto vertices = frame_values<float>(*find_frame(reply, "positions"));
  ASSERT_EQ(vertices.size(), 24u);
  for (int corner = 0; corner < 8; ++corner) {
    const auto c = static_cast<std::size_t>(corner);
    EXPECT_EQ(vertices[3 * c], (corner & 1) ? 4.25f : 0.25f);
    EXPECT_EQ(vertices[3 * c + 1], (corner & 2) ? 3.5f : 0.5f);
    EXPECT_EQ(vertices[3 * c + 2], (corner & 4) ? 2.5f : 0.0f);
  }
  // From a file-frame position inside the closed box, all of it is seen.
  const Reply inside = client_->request(
      7, "station_view", params(R"({"path": "utm_room.obj", "position": [500002, 5400002, 1.2]})"));
  ASSERT_TRUE(inside.ok()) << inside.final;
  EXPECT_NEAR(inside.final["result"]["visible_fraction"].asDouble(), 1.0, 1e-9) << inside.final;
}

}  // namespace
}  // namespace occlusion::testing
