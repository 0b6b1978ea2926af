// A ScanNet mesh is read with the labels file beside it, and a labels file
// with the mesh beside it: the reader opens a second file the client did not
// name. Over the server that file is a path like any other (docs/protocol.md,
// "Conventions"): inside the data directory, or `path_outside_data`. A labels
// file that was a link leading out of the data directory was read.

#include <gtest/gtest.h>

#include <filesystem>

#include "server_fixture.hpp"
#include "support/scannet_scene.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;

constexpr char kScene[] = "scene0001_00";

ScanNetScene small_scene() {
  ScanNetScene scene;
  scene.positions = {{0.0f, 0.0f, 0.0f}, {3.0f, 0.0f, 0.0f}, {0.0f, 3.0f, 0.0f}};
  scene.colours = {{10, 20, 30}, {40, 50, 60}, {70, 80, 90}};
  scene.labels = {2, 2, 1};
  scene.faces = {{0, 1, 2}};
  return scene;
}

class ScanNetSiblingPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    // The whole scene outside (ROOT/outside/scene0001_00/) and a folder in
    // the data directory to put one of its files beside a link to the other.
    write_scannet_scene(server_.files().root() + "/outside", kScene, small_scene());
    fs::create_directories(server_.files().file("scans"));
    client_ = server_.connect();
  }

  static std::string file_name(const std::string& suffix) {
    return std::string(kScene) + "_vh_clean_2" + suffix;
  }

  // DATA/scans/NAME is a copy of the scene's file; beside it, a link to the
  // other one outside. Returns the copy's path as a client names it.
  std::string copy_beside_link(const std::string& copied, const std::string& linked) const {
    const std::string scene = server_.files().root() + "/outside/" + kScene + "/";
    fs::copy_file(scene + copied, server_.files().file("scans/" + copied));
    fs::create_symlink(scene + linked, server_.files().file("scans/" + linked));
    return "scans/" + copied;
  }

  void expect_outside_for_every_reader(const std::string& path, const std::string& sibling) {
    Json::Value with_path(Json::objectValue);
    with_path["path"] = path;
    Json::Value job = with_path;
    job["out"] = "";
    const std::vector<std::pair<std::string, Json::Value>> requests = {
        {"load", with_path}, {"cloud_occlusion", job}, {"mesh_occlusion", job}};
    for (const auto& [command, request] : requests) {
      const Reply reply = client_->request(++id_, command, request, kHangGuard);
      EXPECT_EQ(reply.error_code(), "path_outside_data")
          << command << " " << path << ": " << reply.final;
      EXPECT_TRUE(reply.frames.empty()) << command << " " << path << " sent data";
      const std::string message = reply.final["message"].asString();
      EXPECT_NE(message.find(sibling), std::string::npos) << message;
    }
  }

  TestServer server_;
  std::unique_ptr<BlockingClient> client_;
  std::uint32_t id_ = 0;
};

TEST_F(ScanNetSiblingPaths, AMeshWhoseLabelsFileLeadsOutsideIsRefused) {
  const std::string labels = file_name(".labels.ply");
  expect_outside_for_every_reader(copy_beside_link(file_name(".ply"), labels), labels);
}

TEST_F(ScanNetSiblingPaths, ALabelsFileWhoseMeshLeadsOutsideIsRefused) {
  const std::string mesh = file_name(".ply");
  expect_outside_for_every_reader(copy_beside_link(file_name(".labels.ply"), mesh), mesh);
}

TEST_F(ScanNetSiblingPaths, AMeshAndItsLabelsInsideLoadAsOneLabelledCloud) {
  const std::string scene = server_.files().root() + "/outside/" + kScene + "/";
  for (const std::string& name : {file_name(".ply"), file_name(".labels.ply")}) {
    fs::copy_file(scene + name, server_.files().file("scans/" + name));
  }
  const Reply reply =
      client_->request(++id_, "load", params(R"({"path": "scans/)" + file_name(".ply") + "\"}"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["result"]["points"].asUInt64(), 3u);
  EXPECT_TRUE(reply.final["result"]["has_labels"].asBool()) << reply.final;
}

}  // namespace
}  // namespace occlusion::testing
