// Every kind of bad input gets an error reply with its code (or, for an
// oversized binary message, a clean close), and the server goes on serving.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;

class BadInput : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server::ServerOptions options = TestServer::quiet_options();
    options.max_upload_bytes = 1 << 20;
    server_ = new TestServer(options);
  }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }
  void SetUp() override { client_ = server_->connect(); }

  // The next message, which must be an error with `code`.
  Json::Value expect_error(const std::string& code) {
    const auto message = client_->receive(kHangGuard);
    if (!message) {
      ADD_FAILURE() << "no reply, expected " << code;
      return Json::Value();
    }
    EXPECT_FALSE(message->binary);
    Json::Value json = params(message->data);
    EXPECT_EQ(json["type"].asString(), "error") << message->data;
    EXPECT_EQ(json["code"].asString(), code) << message->data;
    EXPECT_FALSE(json["message"].asString().empty());
    return json;
  }

  // A valid request on the same connection still succeeds.
  void expect_still_serving() {
    const Reply reply = client_->request(9999, "list_files");
    EXPECT_TRUE(reply.ok()) << reply.final;
  }

  const TestData& files() const { return server_->files(); }

  static TestServer* server_;
  std::unique_ptr<BlockingClient> client_;
};

TestServer* BadInput::server_ = nullptr;

TEST_F(BadInput, MalformedJson) {
  client_->send_text("{\"id\": 1, \"command\": ");
  EXPECT_TRUE(expect_error("invalid_json")["id"].isNull());
  client_->send_text("not json at all");
  expect_error("invalid_json");
  client_->send_text(std::string(5000, '[') + std::string(5000, ']'));
  expect_error("invalid_json");
  client_->send_text(R"({"id": 1, "id": 2, "command": "ping"})");
  expect_error("invalid_json");
  expect_still_serving();
}

TEST_F(BadInput, MalformedRequests) {
  for (const char* text :
       {"[1, 2, 3]", "42", R"({"command": "ping"})", R"({"id": -1, "command": "ping"})",
        R"({"id": "7", "command": "ping"})", R"({"id": true, "command": "ping"})",
        R"({"id": 4294967296, "command": "ping"})", R"({"id": 1})", R"({"id": 1, "command": 5})",
        R"({"id": 1, "command": "ping", "params": [1]})",
        R"({"id": 1, "command": "ping", "extra": 1})"}) {
    client_->send_text(text);
    expect_error("invalid_request");
  }
  client_->send_text(R"({"id": 1, "command": "ping", "params": "x"})");
  EXPECT_EQ(expect_error("invalid_request")["id"].asUInt(), 1u);
  expect_still_serving();
}

TEST_F(BadInput, UnknownCommand) {
  const Reply reply = client_->request(3, "format_disk");
  EXPECT_EQ(reply.error_code(), "unknown_command");
  EXPECT_EQ(reply.final["id"].asUInt(), 3u);
  expect_still_serving();
}

TEST_F(BadInput, WrongParameterTypesAndValues) {
  const auto expect_invalid = [&](std::uint32_t id, const std::string& command,
                                  const std::string& json, const std::string& named) {
    const Reply reply = client_->request(id, command, params(json));
    EXPECT_EQ(reply.error_code(), "invalid_request") << json << " -> " << reply.final;
    EXPECT_NE(reply.final["message"].asString().find(named), std::string::npos)
        << reply.final["message"];
  };
  expect_invalid(1, "mesh_occlusion",
                 R"({"path": "sample_room.obj", "samples_per_unit_area": "many"})",
                 "samples_per_unit_area");
  expect_invalid(2, "mesh_occlusion", R"({"path": "sample_room.obj", "colour": 1})", "colour");
  expect_invalid(3, "mesh_occlusion", R"({"path": "sample_room.obj", "pattern": 9})", "pattern");
  expect_invalid(4, "mesh_occlusion", R"({"path": 7})", "path");
  expect_invalid(5, "cloud_occlusion",
                 R"({"path": "s3dis_synthetic/Area_1/office_1", "point_radius": -1})",
                 "'point_radius' must be");  // the key as the request spells it, not --point-radius
  expect_invalid(6, "scan",
                 R"({"path": "s3dis_synthetic/Area_1/office_1", "viewpoints": [[1, 2]]})",
                 "viewpoints");
  expect_invalid(7, "mesh_occlusion", R"({})", "mesh");
  expect_invalid(8, "load", R"({"path": true})", "path");
  expect_invalid(9, "load", R"({})", "path");
  expect_invalid(10, "list_files", R"({"dir": "sample_room.obj"})", "directory");
  expect_invalid(11, "save_polygon", R"({"path": "p.txt", "polygons": [[[0, 0, 0], [1, 0, 0]]]})",
                 "polygon 1");
  expect_invalid(12, "cancel", R"({"target": "x"})", "target");
  expect_still_serving();
}

TEST_F(BadInput, PathsOutsideTheDataDirectory) {
  const auto expect_outside = [&](std::uint32_t id, const std::string& command,
                                  const std::string& json) {
    const Reply reply = client_->request(id, command, params(json));
    EXPECT_EQ(reply.error_code(), "path_outside_data") << json << " -> " << reply.final;
  };
  for (const char* path : {"../outside/secret.txt", "/etc/passwd", "escape/secret.txt",
                           "s3dis_synthetic/../../outside/secret.txt", "escape"}) {
    const std::string quoted = "\"" + std::string(path) + "\"";
    expect_outside(1, "load", R"({"path": )" + quoted + "}");
    expect_outside(2, "scan", R"({"path": )" + quoted + "}");
    expect_outside(3, "list_files", R"({"dir": )" + quoted + "}");
    expect_outside(
        4, "cloud_occlusion",
        R"({"path": "s3dis_synthetic/Area_1/office_1", "polygon_path": )" + quoted + "}");
    expect_outside(5, "mesh_occlusion", R"({"path": "sample_room.obj", "out": )" + quoted + "}");
    expect_outside(6, "save_polygon",
                   R"({"path": )" + quoted + R"(, "polygons": [[[0,0,0],[1,0,0],[0,1,0]]]})");
    expect_outside(7, "evaluate",
                   R"({"ground_truth": [)" + quoted + R"(], "predictions": ["sample_room.obj"]})");
  }
  EXPECT_FALSE(fs::exists(files().root() + "/outside/out"));
  const Reply missing = client_->request(8, "load", params(R"({"path": "nothing/here.ply"})"));
  EXPECT_EQ(missing.error_code(), "not_found");
  expect_still_serving();
}

TEST_F(BadInput, OversizedTextMessage) {
  client_->send_text(R"({"id": 1, "command": "ping", "params": {"pad": ")" +
                     std::string(1100000, 'x') + "\"}}");
  expect_error("message_too_large");
  expect_still_serving();
}

TEST_F(BadInput, OversizedUploadIsRefusedBeforeItsBytes) {
  client_->send_request(1, "upload", params(R"({"name": "big.ply", "size": 2000000})"));
  expect_error("message_too_large");
  // The client had already sent the bytes: they are dropped without a second reply.
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = 1;
  header.count = 1000;
  client_->send_binary(server::encode_frame(header, std::string(1000, 'x').data(), 1000).message);
  expect_still_serving();
}

TEST_F(BadInput, BinaryMessageOverTheTransportLimitClosesThatConnectionOnly) {
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = 1;
  header.count = 3 << 20;
  const std::string bytes(header.count, 'x');
  client_->send_binary(server::encode_frame(header, bytes.data(), bytes.size()).message);
  EXPECT_TRUE(client_->wait_closed(kHangGuard));
  EXPECT_EQ(client_->close_code(), 1009);  // message too big
  client_ = server_->connect();
  expect_still_serving();
}

TEST_F(BadInput, UnexpectedOrMalformedBinary) {
  client_->send_binary("short");
  expect_error("unexpected_binary");
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = 77;
  header.count = 4;
  client_->send_binary(server::encode_frame(header, "abcd", 4).message);
  EXPECT_EQ(expect_error("unexpected_binary")["id"].asUInt(), 77u);
  std::string bad_magic = server::encode_frame(header, "abcd", 4).message;
  bad_magic[0] = 'X';
  client_->send_binary(bad_magic);
  expect_error("unexpected_binary");
  // Announced 10 bytes, sent 4.
  client_->send_request(78, "upload", params(R"({"name": "a.ply", "size": 10})"));
  header.request_id = 78;
  client_->send_binary(server::encode_frame(header, "abcd", 4).message);
  expect_error("unexpected_binary");
  expect_still_serving();
}

// A header whose count disagrees with the bytes after it still names its
// upload: that request gets its answer, under its own id, and the id is free
// again (it was answered with id null, and stayed `duplicate_id`).
TEST_F(BadInput, AnUploadWhoseFrameDisagreesWithItsBytesIsAnsweredUnderItsId) {
  client_->send_request(80, "upload", params(R"({"name": "a.ply", "size": 10})"));
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = 80;
  header.count = 10;  // as announced
  std::string message = server::encode_frame(header, std::string(10, 'x').data(), 10).message;
  message.resize(message.size() - 6);  // 4 bytes follow
  client_->send_binary(message);
  const Json::Value error = expect_error("unexpected_binary");
  EXPECT_EQ(error["id"].asUInt(), 80u) << error;  // not null
  EXPECT_EQ(error["command"].asString(), "upload") << error;
  const Reply reuse = client_->request(80, "ping");
  EXPECT_TRUE(reuse.ok()) << reuse.final;
  expect_still_serving();
}

TEST_F(BadInput, CorruptUploadIsRefusedAndNotStored) {
  const std::string bytes =
      "ply\nformat ascii 1.0\nelement vertex 1000\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n1 1 1\n";
  client_->send_request(
      1, "upload",
      params(R"({"name": "broken.ply", "size": )" + std::to_string(bytes.size()) + "}"));
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = 1;
  header.count = bytes.size();
  client_->send_binary(server::encode_frame(header, bytes.data(), bytes.size()).message);
  const Reply reply = client_->collect(1, kHangGuard);
  EXPECT_EQ(reply.error_code(), "input_error") << reply.final;
  EXPECT_NE(reply.final["message"].asString().find("uploads/broken.ply"), std::string::npos)
      << reply.final["message"];
  EXPECT_FALSE(fs::exists(files().file("uploads/broken.ply")));
  for (const auto& entry : fs::directory_iterator(files().file("uploads"))) {
    EXPECT_NE(entry.path().filename().string().rfind(".upload-", 0), 0u) << entry.path();
  }
  for (const char* name : {"../x.ply", ".hidden.ply", "virus.exe", ""}) {
    Json::Value announce(Json::objectValue);
    announce["name"] = name;
    announce["size"] = 4;
    EXPECT_EQ(client_->request(2, "upload", announce).error_code(), "invalid_request") << name;
  }
  expect_still_serving();
}

TEST_F(BadInput, CorruptFileInTheDataDirectory) {
  std::ofstream(files().file("broken.obj")) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  Reply reply = client_->request(1, "load", params(R"({"path": "broken.obj"})"));
  EXPECT_EQ(reply.error_code(), "input_error");
  EXPECT_NE(reply.final["message"].asString().find("broken.obj:3"), std::string::npos)
      << reply.final["message"];
  EXPECT_EQ(reply.final["message"].asString().find(files().data()), std::string::npos);
  reply = client_->request(2, "mesh_occlusion", params(R"({"path": "broken.obj"})"));
  EXPECT_EQ(reply.error_code(), "input_error");
  expect_still_serving();
}

TEST_F(BadInput, DuplicateIdOfARunningRequest) {
  client_->send_request(5, "cloud_occlusion", long_job());
  client_->send_request(5, "ping");
  client_->send_request(5, "load", params(R"({"path": "sample_room.obj"})"));
  for (int i = 0; i < 2; ++i) {
    const Reply reply = client_->collect(5, kHangGuard);
    EXPECT_EQ(reply.error_code(), "duplicate_id") << reply.final;
  }
  EXPECT_TRUE(client_->request(6, "cancel", params(R"({"target": 5})")).ok());
  EXPECT_EQ(client_->collect(5, kHangGuard).error_code(), "cancelled");
  expect_still_serving();
}

TEST_F(BadInput, ForeignWebOriginIsRefused) {
  EXPECT_THROW(server_->connect("http://evil.example"), std::runtime_error);
  EXPECT_NO_THROW(server_->connect("http://localhost:5173"));
  EXPECT_NO_THROW(server_->connect("http://127.0.0.1:" + std::to_string(server_->port())));
  expect_still_serving();
}

}  // namespace
}  // namespace occlusion::testing
