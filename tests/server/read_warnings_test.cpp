// What reading a file found that the user should know (CloudReadReport::
// warnings: a depth frame with depths no indoor sensor measures) comes with
// `load`'s reply, as -poc reports it first among its warnings, so the viewer
// shows it when the file is shown, not only after a job. The warning names
// the file as the client knows it, for a load from the cache and an upload too.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "server_fixture.hpp"
#include "support/png_writer.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kWidth = 16, kHeight = 12;

// A frame of a wall `millimetres` in front of the camera, every pixel measured.
std::string descriptor(const std::string& depth) {
  Json::Value json(Json::objectValue);
  json["depth"] = depth;
  json["intrinsics"]["fx"] = 10;
  json["intrinsics"]["fy"] = 10;
  json["intrinsics"]["cx"] = 7.5;
  json["intrinsics"]["cy"] = 5.5;
  json["depth_scale"] = 1000;
  return Json::writeString(Json::StreamWriterBuilder(), json);
}

void write_wall(const std::string& path, std::uint16_t millimetres) {
  write_depth_png(path, kWidth, kHeight, std::vector<std::uint16_t>(kWidth * kHeight, millimetres));
}

class ReadWarnings : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(server_.files().file("frames"));
    // 30 m: beyond kMaxIndoorDepthMetres (20 m), as a raw SUN RGB-D PNG reads.
    write_wall(server_.files().file("frames/far.png"), 30000);
    write_wall(server_.files().file("frames/near.png"), 2500);
    std::ofstream(server_.files().file("frames/far.frame.json")) << descriptor("far.png");
    std::ofstream(server_.files().file("frames/near.frame.json")) << descriptor("near.png");
    client_ = server_.connect();
  }

  Json::Value load(const std::string& path) {
    const Reply reply = client_->request(++id_, "load", params(R"({"path": ")" + path + "\"}"));
    EXPECT_TRUE(reply.ok()) << path << ": " << reply.final;
    return reply.final["result"];
  }

  TestServer server_;
  std::unique_ptr<BlockingClient> client_;
  std::uint32_t id_ = 0;
};

TEST_F(ReadWarnings, LoadSaysWhatTheCliSaysOfAFrameBeyondIndoorDepths) {
  const Json::Value result = load("frames/far.frame.json");
  ASSERT_TRUE(result["warnings"].isArray()) << result;
  ASSERT_EQ(result["warnings"].size(), 1u) << result["warnings"];
  const std::string warning = result["warnings"][0].asString();
  // Named as the client names it: nothing of the server's own directories.
  EXPECT_EQ(warning.rfind("frames/far.frame.json: ", 0), 0u) << warning;
  EXPECT_EQ(warning.find(server_.files().data()), std::string::npos) << warning;

  // The CLI reads the same file with the same warning, first among -poc's.
  const Json::Value cli =
      run_cli_json("-poc frames/far.frame.json --num-rays-per-vp 200", server_.files().data());
  ASSERT_TRUE(cli.isObject());
  ASSERT_FALSE(cli["warnings"].empty()) << cli;
  EXPECT_EQ(cli["warnings"][0].asString(), warning);

  // From the cache, the same.
  const Json::Value again = load("frames/far.frame.json");
  EXPECT_TRUE(again["cached"].asBool());
  EXPECT_EQ(again["warnings"], result["warnings"]);
}

TEST_F(ReadWarnings, AFrameWithinIndoorDepthsLoadsWithNone) {
  const Json::Value result = load("frames/near.frame.json");
  ASSERT_TRUE(result["warnings"].isArray()) << result;
  EXPECT_TRUE(result["warnings"].empty()) << result["warnings"];
  EXPECT_EQ(result["points"].asUInt64(), kWidth * kHeight);
}

// An upload is read from a temporary name before it is stored: its warning
// names it as stored, uploads/NAME, the path the client loads it by next.
TEST_F(ReadWarnings, AnUploadsWarningNamesItAsStored) {
  fs::create_directories(server_.files().file("uploads"));
  write_wall(server_.files().file("uploads/far.png"), 30000);
  const std::string bytes = descriptor("far.png");
  Json::Value announce(Json::objectValue);
  announce["name"] = "sent.frame.json";
  announce["size"] = Json::UInt64(bytes.size());
  const std::uint32_t id = ++id_;
  client_->send_request(id, "upload", announce);
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = id;
  header.count = bytes.size();
  client_->send_binary(server::encode_frame(header, bytes.data(), bytes.size()).message);
  const Reply reply = client_->collect(id, kHangGuard);
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& warnings = reply.final["result"]["warnings"];
  ASSERT_EQ(warnings.size(), 1u) << reply.final;
  EXPECT_EQ(warnings[0].asString().rfind("uploads/sent.frame.json: ", 0), 0u) << warnings[0];
  // Loaded by that name, it says the same.
  EXPECT_EQ(load("uploads/sent.frame.json")["warnings"], warnings);
}

}  // namespace
}  // namespace occlusion::testing
