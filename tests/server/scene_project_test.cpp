// A project file over the server: `load` reads its scans as one scene with
// the stations where their poses put them (files/projects/, worked by hand in
// SOURCES.md there), and every path a project names is a path like any other
// a client gives (docs/protocol.md, "Conventions"): a scan or a pose file
// outside the data directory is `path_outside_data`, by a relative path, an
// absolute one or a link.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kFiles = fs::path(OCCLUSION_SOURCE_DIR) / "files";

class SceneProjectServer : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::copy(kFiles / "projects", server_.files().file("projects"), fs::copy_options::recursive);
    fs::create_directories(server_.files().file("e57"));
    fs::copy_file(kFiles / "e57/translationWithoutRotation.e57",
                  server_.files().file("e57/translationWithoutRotation.e57"));
    client_ = server_.connect();
  }

  // DATA/projects/NAME.project.json holding `text`; its path as a client names it.
  std::string project(const std::string& name, const std::string& text) const {
    const std::string path = "projects/" + name + ".project.json";
    std::ofstream(server_.files().file(path)) << text;
    return path;
  }

  Reply load(const std::string& path) {
    Json::Value request(Json::objectValue);
    request["path"] = path;
    return client_->request(++id_, "load", request, kHangGuard);
  }

  void expect_outside(const std::string& path) {
    const Reply reply = load(path);
    EXPECT_EQ(reply.error_code(), "path_outside_data") << path << ": " << reply.final;
    EXPECT_TRUE(reply.frames.empty()) << path << " sent data";
  }

  TestServer server_;
  std::unique_ptr<BlockingClient> client_;
  std::uint32_t id_ = 0;
};

TEST_F(SceneProjectServer, LoadsAProjectWithItsStations) {
  const Reply reply = load("projects/mixed.project.json");
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  EXPECT_EQ(result["points"].asUInt64(), 16u);
  const Json::Value& stations = result["stations"];
  ASSERT_EQ(stations.size(), 4u);
  const double by_hand[4][3] = {{5, 4, 6}, {2, 0, 0}, {0, 7, 0.5}, {0, 3, 0}};
  const char* names[] = {nullptr, "pcd", "wall", "text"};
  for (Json::ArrayIndex s = 0; s < 4; ++s) {
    for (Json::ArrayIndex axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(stations[s]["position"][axis].asDouble(), by_hand[s][axis], 1e-9) << s;
    }
    if (names[s] != nullptr) {
      EXPECT_EQ(stations[s]["name"].asString(), names[s]);
    }
  }
  // Only the PLY has colours: dropped, and the warning names the project as the client does.
  ASSERT_EQ(result["warnings"].size(), 1u) << result;
  EXPECT_EQ(result["warnings"][0].asString().rfind("projects/mixed.project.json: ", 0), 0u)
      << result["warnings"][0];
}

TEST_F(SceneProjectServer, AScanOrPoseFileOutsideIsRefused) {
  const std::string identity = R"("pose": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]])";
  const std::string outside = server_.files().root() + "/outside/secret.txt";
  expect_outside(
      project("up", R"({"scans": [{"path": "../../outside/secret.txt", )" + identity + "}]}"));
  expect_outside(
      project("absolute", R"({"scans": [{"path": ")" + outside + "\", " + identity + "}]}"));
  expect_outside(
      project("link", R"({"scans": [{"path": "../escape/secret.txt", )" + identity + "}]}"));
  // A scan inside, its pose file outside.
  std::ofstream(server_.files().root() + "/outside/pose.txt")
      << "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  expect_outside(project("pose_up", R"({"scans": [{"path": "wall.pcd",
                                          "pose_file": "../../outside/pose.txt"}]})"));
  // The same scan and pose inside load.
  std::ofstream(server_.files().file("projects/pose.txt"))
      << "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  const Reply inside =
      load(project("pose_in", R"({"scans": [{"path": "wall.pcd", "pose_file": "pose.txt"}]})"));
  EXPECT_TRUE(inside.ok()) << inside.final;
}

}  // namespace
}  // namespace occlusion::testing
