// Loaded scenes are reused while their files are unchanged, within a memory bound.

#include "../../src/server/scene_cache.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<server::LoadedScene> scene_of(std::size_t bytes) {
  auto scene = std::make_shared<server::LoadedScene>();
  std::vector<std::uint8_t> payload(bytes);
  scene->frames.push_back(
      server::make_frame(server::FrameKind::kColours, payload.data(), bytes, 1));
  return scene;
}

TEST(SceneCache, EvictsTheLeastRecentlyUsedBeyondItsBound) {
  const std::size_t size = scene_of(10000)->bytes();
  server::SceneCache cache(3 * size);
  cache.insert("a", scene_of(10000));
  cache.insert("b", scene_of(10000));
  cache.insert("c", scene_of(10000));
  EXPECT_NE(cache.find("a"), nullptr);  // a is now the most recent
  cache.insert("d", scene_of(10000));
  EXPECT_EQ(cache.find("b"), nullptr);
  EXPECT_NE(cache.find("a"), nullptr);
  EXPECT_NE(cache.find("c"), nullptr);
  EXPECT_NE(cache.find("d"), nullptr);
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_LE(cache.bytes(), 3 * size);
  cache.insert("huge", scene_of(10 * size));  // larger than the bound: not kept
  EXPECT_EQ(cache.find("huge"), nullptr);
  EXPECT_EQ(cache.size(), 3u);
}

TEST(SceneCache, KeyChangesWhenAFileOrAFileInAFolderChanges) {
  const TestData files;
  const fs::path room = files.file("s3dis_synthetic/Area_1/office_1");
  const std::string before = server::scene_key(room, "");
  EXPECT_EQ(server::scene_key(room, ""), before);
  EXPECT_NE(server::scene_key(room, "skip_bad_lines"), before);
  std::ofstream(room / "Annotations/clutter_1.txt", std::ios::app) << "0.5 0.5 0.5 1 2 3\n";
  EXPECT_NE(server::scene_key(room, ""), before);
}

TEST(SceneCache, ServerReloadsAChangedFile) {
  TestServer server;
  auto client = server.connect();
  const Json::Value load = params(R"({"path": "cloud.xyz"})");
  std::ofstream(server.files().file("cloud.xyz")) << "0 0 0\n1 0 0\n0 1 0\n";
  Reply reply = client->request(1, "load", load);
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_FALSE(reply.final["result"]["cached"].asBool());
  reply = client->request(2, "load", load);
  EXPECT_TRUE(reply.final["result"]["cached"].asBool());
  std::ofstream(server.files().file("cloud.xyz"), std::ios::app) << "0 0 1\n";
  reply = client->request(3, "load", load);
  EXPECT_FALSE(reply.final["result"]["cached"].asBool());
  EXPECT_EQ(reply.final["result"]["points"].asUInt(), 4u);
}

TEST(SceneCache, ServerWithoutCacheMemoryNeverCaches) {
  server::ServerOptions options = TestServer::quiet_options();
  options.cache_bytes = 0;
  TestServer server(options);
  auto client = server.connect();
  for (std::uint32_t id = 1; id <= 2; ++id) {
    const Reply reply = client->request(id, "load", params(R"({"path": "sample_room.obj"})"));
    ASSERT_TRUE(reply.ok());
    EXPECT_FALSE(reply.final["result"]["cached"].asBool());
  }
}

}  // namespace
}  // namespace occlusion::testing
