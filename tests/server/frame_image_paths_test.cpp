// A depth frame's descriptor names its images, and over the server those are
// paths like any other a client gives (docs/protocol.md, "Conventions"):
// inside the data directory, or `path_outside_data`, whichever command reads
// the frame, whether the descriptor lies in the data directory or was
// uploaded, and whether or not the file outside exists. Such images were
// read, and their pixels came back to the client as positions.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "server_fixture.hpp"
#include "support/png_writer.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kWidth = 8, kHeight = 6;

// A plane 2 m in front of the camera, every pixel measured.
void write_depth(const std::string& path) {
  write_depth_png(path, kWidth, kHeight, std::vector<std::uint16_t>(kWidth * kHeight, 2000));
}

std::string descriptor_text(const std::string& depth, const std::string& colour) {
  Json::Value json(Json::objectValue);
  json["depth"] = depth;
  if (!colour.empty()) json["colour"] = colour;
  json["intrinsics"]["fx"] = 10;
  json["intrinsics"]["fy"] = 10;
  json["intrinsics"]["cx"] = 3.5;
  json["intrinsics"]["cy"] = 2.5;
  json["depth_scale"] = 1000;
  return Json::writeString(Json::StreamWriterBuilder(), json);
}

class FrameImagePaths : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(server_.files().file("frames"));
    write_depth(server_.files().file("frames/depth.png"));
    write_depth(outside("depth.png"));
    write_8bit_png(outside("rgb.png"), kWidth, kHeight, 3,
                   std::vector<std::uint8_t>(3 * kWidth * kHeight, 200));
    client_ = server_.connect();
  }

  // A file beside the data directory (ROOT/outside; DATA/escape links there).
  std::string outside(const std::string& name) const {
    return server_.files().root() + "/outside/" + name;
  }

  // DATA/frames/NAME.frame.json naming `depth` (and `colour`); its path as a client names it.
  std::string frame(const std::string& name, const std::string& depth,
                    const std::string& colour = "") const {
    const std::string path = "frames/" + name + ".frame.json";
    std::ofstream(server_.files().file(path)) << descriptor_text(depth, colour);
    return path;
  }

  // Every command that reads the frame answers `path_outside_data`.
  void expect_outside_for_every_reader(const std::string& path) {
    Json::Value with_path(Json::objectValue);
    with_path["path"] = path;
    Json::Value view = with_path;
    view["position"] = params("[0, 0, 1]");
    Json::Value job = with_path;
    job["out"] = "";
    const std::vector<std::pair<std::string, Json::Value>> requests = {
        {"load", with_path}, {"station_view", view}, {"cloud_occlusion", job}, {"plan", job}};
    for (const auto& [command, request] : requests) {
      const Reply reply = client_->request(++id_, command, request, kHangGuard);
      EXPECT_EQ(reply.error_code(), "path_outside_data")
          << command << " " << path << ": " << reply.final;
      EXPECT_TRUE(reply.frames.empty()) << command << " " << path << " sent data";
      expect_names(reply, path);
    }
  }

  // The refusal names the descriptor as the client knows it.
  static void expect_names(const Reply& reply, const std::string& descriptor) {
    const std::string message = reply.final["message"].asString();
    EXPECT_NE(message.find("'" + descriptor + "'"), std::string::npos) << message;
  }

  TestServer server_;
  std::unique_ptr<BlockingClient> client_;
  std::uint32_t id_ = 0;
};

TEST_F(FrameImagePaths, ImagesInsideTheDataDirectoryAreRead) {
  fs::create_directories(server_.files().file("frames/images"));
  write_depth(server_.files().file("frames/images/depth.png"));
  for (const char* depth : {"depth.png", "images/../depth.png", "images/depth.png"}) {
    const Reply reply =
        client_->request(++id_, "load", params(R"({"path": ")" + frame("inside", depth) + "\"}"));
    ASSERT_TRUE(reply.ok()) << depth << ": " << reply.final;
    EXPECT_EQ(reply.final["result"]["points"].asUInt64(), kWidth * kHeight) << depth;
  }
}

TEST_F(FrameImagePaths, ADepthImageOutsideIsRefusedByEveryCommandThatReadsTheFrame) {
  expect_outside_for_every_reader(frame("up", "../../outside/depth.png"));
  expect_outside_for_every_reader(frame("absolute", outside("depth.png")));
  expect_outside_for_every_reader(frame("link", "../escape/depth.png"));
  // Inside by its name, outside once the link is followed.
  fs::create_directory_symlink("../../outside", server_.files().file("frames/out"));
  expect_outside_for_every_reader(frame("nested_link", "out/depth.png"));
}

TEST_F(FrameImagePaths, AColourImageOutsideIsRefusedToo) {
  expect_outside_for_every_reader(frame("colour_up", "depth.png", "../../outside/rgb.png"));
  expect_outside_for_every_reader(frame("colour_absolute", "depth.png", outside("rgb.png")));
}

// The answer says nothing of the file outside: the same code whether it
// exists or not.
TEST_F(FrameImagePaths, AnImageOutsideIsRefusedAlikeWhetherOrNotItExists) {
  ASSERT_FALSE(fs::exists(outside("missing.png")));
  for (const char* name : {"depth.png", "missing.png"}) {
    for (const std::string& depth : {std::string("../../outside/") + name, outside(name)}) {
      const Reply reply =
          client_->request(++id_, "load", params(R"({"path": ")" + frame("probe", depth) + "\"}"));
      EXPECT_EQ(reply.error_code(), "path_outside_data") << depth << ": " << reply.final;
    }
  }
}

// An uploaded descriptor is read where it is stored, DATA/uploads: it names
// nothing outside either, and is not stored.
TEST_F(FrameImagePaths, AnUploadedDescriptorCannotNameAnImageOutside) {
  std::uint32_t upload_id = 100;
  for (const std::string& depth : {outside("depth.png"), std::string("../../outside/depth.png")}) {
    const std::string bytes = descriptor_text(depth, "");
    Json::Value announce(Json::objectValue);
    announce["name"] = "sent.frame.json";
    announce["size"] = Json::UInt64(bytes.size());
    client_->send_request(++upload_id, "upload", announce);
    server::FrameHeader header;
    header.kind = server::FrameKind::kUpload;
    header.request_id = upload_id;
    header.count = bytes.size();
    client_->send_binary(server::encode_frame(header, bytes.data(), bytes.size()).message);
    const Reply reply = client_->collect(upload_id, kHangGuard);
    EXPECT_EQ(reply.error_code(), "path_outside_data") << depth << ": " << reply.final;
    EXPECT_TRUE(reply.frames.empty()) << depth << " sent data";
    expect_names(reply, "uploads/sent.frame.json");
    EXPECT_FALSE(fs::exists(server_.files().file("uploads/sent.frame.json"))) << depth;
  }
}

}  // namespace
}  // namespace occlusion::testing
