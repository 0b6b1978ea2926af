// The live station (`station_view`): what a scanner at a position sees of a
// loaded scene, against scenes whose answer is known (two rooms behind a
// closed wall) and against the jobs whose rules it follows (-fscan from one
// viewpoint, -moc from one viewpoint), and with a scanner's limits against
// what a plan with the same limits counts for a station there.

#include <gtest/gtest.h>

#include <cmath>

#include "occlusion/io/cloud_io.hpp"
#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

// Two 4 x 4 x 3 rooms side by side (x in [0, 4] and [4, 8]) with a closed
// wall between them at x = 4: the six faces of the box and the wall, points
// on a 0.1 grid.
PointCloud two_rooms() {
  PointCloud cloud;
  const double step = 0.1;
  const auto plane = [&](int axis, double at, double u0, double u1, double v0, double v1) {
    const int ua = axis == 0 ? 1 : 0, va = axis == 2 ? 1 : 2;
    for (double u = u0; u <= u1 + 1e-9; u += step) {
      for (double v = v0; v <= v1 + 1e-9; v += step) {
        Eigen::Vector3f p;
        p[axis] = static_cast<float>(at);
        p[ua] = static_cast<float>(u);
        p[va] = static_cast<float>(v);
        cloud.positions.push_back(p);
      }
    }
  };
  plane(2, 0.0, 0.05, 7.95, 0.05, 3.95);  // floor (x, y)
  plane(2, 3.0, 0.05, 7.95, 0.05, 3.95);  // ceiling
  plane(1, 0.0, 0.05, 7.95, 0.05, 2.95);  // wall y = 0 (x, z)
  plane(1, 4.0, 0.05, 7.95, 0.05, 2.95);  // wall y = 4
  plane(0, 0.0, 0.05, 3.95, 0.05, 2.95);  // wall x = 0 (y, z)
  plane(0, 8.0, 0.05, 3.95, 0.05, 2.95);  // wall x = 8
  plane(0, 4.0, 0.05, 3.95, 0.05, 2.95);  // the wall between the rooms
  return cloud;
}

class LiveStation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server_ = new TestServer();
    cloud_ = new PointCloud(two_rooms());
    write_cloud(server_->files().file("two_rooms.ply"), *cloud_);
  }
  static void TearDownTestSuite() {
    delete server_;
    delete cloud_;
    server_ = nullptr;
    cloud_ = nullptr;
  }
  void SetUp() override { client_ = server_->connect(); }

  Reply view(std::uint32_t id, const std::string& json) {
    return client_->request(id, "station_view", params(json));
  }
  // The seen flags of a cloud reply.
  static std::vector<std::uint16_t> seen(const Reply& reply) {
    const std::string* frame = find_frame(reply, "visible_count");
    return frame ? frame_values<std::uint16_t>(*frame) : std::vector<std::uint16_t>{};
  }

  static TestServer* server_;
  static PointCloud* cloud_;
  std::unique_ptr<BlockingClient> client_;
};

TestServer* LiveStation::server_ = nullptr;
PointCloud* LiveStation::cloud_ = nullptr;

TEST_F(LiveStation, TheWallHidesTheOtherRoomAndTheStationSeesItsOwn) {
  const Reply left = view(1, R"({"path": "two_rooms.ply", "position": [2, 2, 1.5]})");
  ASSERT_TRUE(left.ok()) << left.final;
  const auto flags = seen(left);
  ASSERT_EQ(flags.size(), cloud_->size());
  std::size_t own = 0, own_seen = 0, other = 0, other_seen = 0, seen_total = 0;
  for (std::size_t i = 0; i < flags.size(); ++i) {
    ASSERT_LE(flags[i], 1u);
    seen_total += flags[i];
    const float x = cloud_->positions[i].x();
    if (x < 3.9f) {
      ++own;
      own_seen += flags[i];
    } else if (x > 4.1f) {
      ++other;
      other_seen += flags[i];
    }
  }
  // A convex room is seen whole but for points at its corners, where the
  // neighbouring face's discs stand in front of them; nothing passes the wall.
  EXPECT_GT(static_cast<double>(own_seen), 0.97 * static_cast<double>(own));
  EXPECT_EQ(other_seen, 0u);
  const Json::Value& result = left.final["result"];
  EXPECT_EQ(result["visible_points"].asUInt64(), seen_total);
  EXPECT_EQ(result["points"].asUInt64(), cloud_->size());
  EXPECT_EQ(result["model"]["targets"].asString(), "points");
  EXPECT_EQ(result["model"]["point_model"]["primitive"].asString(), "disc");

  // From the other room: the mirror answer, from the model already built.
  const Reply right = view(2, R"({"path": "two_rooms.ply", "position": [6, 2, 1.5]})");
  ASSERT_TRUE(right.ok()) << right.final;
  EXPECT_FALSE(right.final["result"]["model_built"].asBool());
  const auto mirrored = seen(right);
  ASSERT_EQ(mirrored.size(), cloud_->size());
  for (std::size_t i = 0; i < mirrored.size(); ++i) {
    const float x = cloud_->positions[i].x();
    if (x < 3.9f) {
      EXPECT_EQ(mirrored[i], 0u) << "point " << i;
    }
  }
}

TEST_F(LiveStation, AnswersAsTheScanJobFromOneViewpoint) {
  for (const char* model : {R"("primitive": "disc")", R"("primitive": "sphere")"}) {
    const std::string common = std::string(R"({"path": "two_rooms.ply", )") + model;
    const Reply live = view(3, common + R"(, "position": [1.3, 0.7, 2.1]})");
    ASSERT_TRUE(live.ok()) << live.final;
    const Reply scan = client_->request(
        4, "scan", params(common + R"(, "viewpoints": [[1.3, 0.7, 2.1]], "out": ""})"));
    ASSERT_TRUE(scan.ok()) << scan.final;
    const auto counts = frame_values<std::uint16_t>(*find_frame(scan, "visible_count"));
    EXPECT_EQ(seen(live), counts) << model;
    EXPECT_EQ(live.final["result"]["visible_points"].asUInt64(),
              scan.final["result"]["visible_points"].asUInt64());
  }
}

TEST_F(LiveStation, MeshFacesAsMeshOcclusionFromOneViewpoint) {
  const Reply live = view(5, R"({"path": "sample_room.obj", "position": [1, 1, 1.2],
                                 "samples_per_unit_area": 20, "seed": 3})");
  ASSERT_TRUE(live.ok()) << live.final;
  const Reply job = client_->request(
      6, "mesh_occlusion", params(R"({"path": "sample_room.obj", "viewpoints": [[1, 1, 1.2]],
                 "samples_per_unit_area": 20, "seed": 3, "out": ""})"));
  ASSERT_TRUE(job.ok()) << job.final;
  const auto live_faces = frame_values<float>(*find_frame(live, "face_visible_fraction"));
  const auto job_faces = frame_values<float>(*find_frame(job, "face_visible_fraction"));
  ASSERT_FALSE(live_faces.empty());
  EXPECT_EQ(live_faces, job_faces);
  EXPECT_NEAR(live.final["result"]["visible_fraction"].asDouble(),
              1.0 - job.final["result"]["occlusion_level"].asDouble(), 1e-9);
}

// What `plan` with these limits counts for a station placed at `position`:
// per point, whether that station (the placed one, rank 1) covers it.
std::vector<std::uint16_t> plan_covers(BlockingClient& client, std::uint32_t id,
                                       const std::string& position, const std::string& limits) {
  const Reply plan = client.request(
      id, "plan",
      params(R"({"path": "two_rooms.ply", "stations": 1, "improve": false, "placed": [)" +
             position + "], " + limits + R"(, "out": ""})"));
  EXPECT_TRUE(plan.ok()) << plan.final;
  EXPECT_EQ(plan.final["result"]["stations"][0]["existing"].asBool(), true) << plan.final;
  std::vector<std::uint16_t> covered;
  if (const std::string* frame = find_frame(plan, "covered_by")) {
    for (const std::int32_t rank : frame_values<std::int32_t>(*frame)) covered.push_back(rank == 1);
  }
  return covered;
}

TEST_F(LiveStation, WithAMaxRangeSeesWhatThePlanCountsAndNothingFarther) {
  const Reply open = view(20, R"({"path": "two_rooms.ply", "position": [2, 2, 1.5]})");
  ASSERT_TRUE(open.ok()) << open.final;
  const Reply near = view(21, R"({"path": "two_rooms.ply", "position": [2, 2, 1.5],
                                 "max_range": 1.8})");
  ASSERT_TRUE(near.ok()) << near.final;
  EXPECT_EQ(near.final["result"]["limits"]["max_range"].asDouble(), 1.8);
  const auto unlimited = seen(open), limited = seen(near);
  ASSERT_EQ(limited.size(), cloud_->size());
  // By hand: beyond 1.8 nothing is seen; within it, what the station sees
  // without the limit (1e-4 spares float rounding at the boundary).
  const Eigen::Vector3f station(2, 2, 1.5);
  std::size_t beyond = 0, within_seen = 0;
  for (std::size_t i = 0; i < limited.size(); ++i) {
    const float distance = (cloud_->positions[i] - station).norm();
    if (distance > 1.8f + 1e-4f) {
      ++beyond;
      EXPECT_EQ(limited[i], 0u) << "point " << i << " at " << distance;
    } else if (distance < 1.8f - 1e-4f) {
      EXPECT_EQ(limited[i], unlimited[i]) << "point " << i << " at " << distance;
      within_seen += limited[i];
    }
  }
  EXPECT_GT(beyond, cloud_->size() / 2);  // most of the two rooms is farther
  EXPECT_GT(within_seen, 100u);           // the floor and ceiling under and over it
  // And exactly what the plan's coverage gives a station there.
  EXPECT_EQ(limited, plan_covers(*client_, 22, "[2, 2, 1.5]", R"("max_range": 1.8)"));
}

TEST_F(LiveStation, WithAnIncidenceOrElevationLimitSeesWhatThePlanCounts) {
  const Reply open = view(23, R"({"path": "two_rooms.ply", "position": [2.3, 1.6, 1.5]})");
  ASSERT_TRUE(open.ok()) << open.final;
  const auto unlimited = seen(open);
  // The vertical field of view from the horizontal up: the floor (all below
  // the station) is out of it, the ceiling as seen before.
  const Reply up = view(24, R"({"path": "two_rooms.ply", "position": [2.3, 1.6, 1.5],
                               "min_elevation": 0})");
  ASSERT_TRUE(up.ok()) << up.final;
  const auto upward = seen(up);
  ASSERT_EQ(upward.size(), cloud_->size());
  std::size_t ceiling_seen = 0;
  for (std::size_t i = 0; i < upward.size(); ++i) {
    const float z = cloud_->positions[i].z();
    if (z < 1.49f) {
      EXPECT_EQ(upward[i], 0u) << "point " << i;
    } else if (z > 1.51f) {
      EXPECT_EQ(upward[i], unlimited[i]) << "point " << i;
    }
    if (z > 2.99f) ceiling_seen += upward[i];
  }
  EXPECT_GT(ceiling_seen, 1000u);
  EXPECT_EQ(upward, plan_covers(*client_, 25, "[2.3, 1.6, 1.5]", R"("min_elevation": 0)"));

  // Grazing angles: a point met more than 45 degrees off its surface's normal
  // is not seen. By hand on the floor, 1.5 below the station (away from the
  // walls, where the discs' normals are the floor's): a point at horizontal
  // distance r is met atan(r / 1.5) off its normal, so within r = 1.26 (40
  // degrees) it is seen as before and beyond r = 1.79 (50 degrees) not.
  const Reply grazing = view(26, R"({"path": "two_rooms.ply", "position": [2.3, 1.6, 1.5],
                                    "max_incidence": 45})");
  ASSERT_TRUE(grazing.ok()) << grazing.final;
  const auto steep = seen(grazing);
  std::size_t near_kept = 0, far_dropped = 0;
  for (std::size_t i = 0; i < steep.size(); ++i) {
    EXPECT_LE(steep[i], unlimited[i]) << "point " << i;
    const Eigen::Vector3f& p = cloud_->positions[i];
    const bool floor =
        p.z() < 0.01f && p.x() > 0.3f && p.x() < 3.6f && p.y() > 0.3f && p.y() < 3.7f;
    if (!floor || !unlimited[i]) continue;
    const float r = std::hypot(p.x() - 2.3f, p.y() - 1.6f);
    if (r < 1.26f) {
      EXPECT_EQ(steep[i], 1u) << "point " << i;
      ++near_kept;
    } else if (r > 1.79f) {
      EXPECT_EQ(steep[i], 0u) << "point " << i;
      ++far_dropped;
    }
  }
  EXPECT_GT(near_kept, 300u);
  EXPECT_GT(far_dropped, 100u);
  EXPECT_EQ(steep, plan_covers(*client_, 27, "[2.3, 1.6, 1.5]", R"("max_incidence": 45)"));
}

TEST_F(LiveStation, AMeshsVisibleAreaWithAMaxRangeIsThePlansCoverage) {
  // Both weigh a sample by its face's area over the face's samples, so the
  // live station's visible fraction is the plan's coverage by that station.
  const std::string mesh = R"("path": "sample_room.obj", "samples_per_unit_area": 20, "seed": 3)";
  const Reply open = view(40, "{" + mesh + R"(, "position": [1, 1, 1.2]})");
  const Reply near = view(41, "{" + mesh + R"(, "position": [1, 1, 1.2], "max_range": 1.5})");
  ASSERT_TRUE(open.ok()) << open.final;
  ASSERT_TRUE(near.ok()) << near.final;
  const double limited = near.final["result"]["visible_fraction"].asDouble();
  EXPECT_LT(limited, open.final["result"]["visible_fraction"].asDouble() - 0.05);
  const Reply plan = client_->request(
      42, "plan", params("{" + mesh + R"(, "stations": 1, "improve": false, "placed": [[1, 1, 1.2]],
                              "max_range": 1.5, "out": ""})"));
  ASSERT_TRUE(plan.ok()) << plan.final;
  const Json::Value& first = plan.final["result"]["stations"][0];
  EXPECT_TRUE(first["existing"].asBool()) << first;
  EXPECT_NEAR(first["coverage"].asDouble(), limited, 1e-9) << plan.final["result"]["stations"];
}

TEST_F(LiveStation, RefusesLimitsAsThePlanDoes) {
  const Reply negative = view(30, R"({"path": "two_rooms.ply", "position": [2, 2, 1.5],
                                     "max_range": -1})");
  EXPECT_EQ(negative.error_code(), "invalid_request") << negative.final;
  EXPECT_NE(negative.final["message"].asString().find("max_range"), std::string::npos)
      << negative.final;
  const Reply crossed = view(31, R"({"path": "two_rooms.ply", "position": [2, 2, 1.5],
                                    "min_elevation": 30, "max_elevation": 10})");
  EXPECT_EQ(crossed.error_code(), "invalid_request") << crossed.final;
  EXPECT_NE(crossed.final["message"].asString().find("min_elevation"), std::string::npos)
      << crossed.final;
  const Reply up = view(32, R"({"path": "two_rooms.ply", "position": [2, 2, 1.5], "up": "w"})");
  EXPECT_EQ(up.error_code(), "invalid_request") << up.final;
}

TEST_F(LiveStation, RefusesWhatItCannotTrace) {
  EXPECT_EQ(view(7, R"({"path": "two_rooms.ply"})").error_code(), "invalid_request");
  EXPECT_EQ(view(8, R"({"path": "two_rooms.ply", "position": [1, 2]})").error_code(),
            "invalid_request");
  EXPECT_EQ(view(9, R"({"path": "two_rooms.ply", "position": [1, 2, "x"]})").error_code(),
            "invalid_request");
  // A mesh's key on a cloud, a key neither takes, a value out of its range.
  EXPECT_EQ(view(10, R"({"path": "two_rooms.ply", "position": [1, 1, 1],
                        "samples_per_unit_area": 5})")
                .error_code(),
            "invalid_request");
  EXPECT_EQ(
      view(11, R"({"path": "two_rooms.ply", "position": [1, 1, 1], "pattern": 2})").error_code(),
      "invalid_request");
  const Reply range =
      view(12, R"({"path": "two_rooms.ply", "position": [1, 1, 1], "disc_coverage": 2})");
  EXPECT_EQ(range.error_code(), "invalid_request") << range.final;
  EXPECT_NE(range.final["message"].asString().find("disc_coverage"), std::string::npos)
      << range.final;
  // Too far for float to resolve the points.
  const Reply far = view(13, R"({"path": "two_rooms.ply", "position": [1e12, 0, 0]})");
  EXPECT_EQ(far.error_code(), "invalid_request") << far.final;
  EXPECT_EQ(view(14, R"({"path": "missing.ply", "position": [1, 1, 1]})").error_code(),
            "not_found");
}

}  // namespace
}  // namespace occlusion::testing
