#include "server_fixture.hpp"

#include <gtest/gtest.h>
#include <json/reader.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace occlusion::testing {

namespace fs = std::filesystem;

TestData::TestData() {
  static std::atomic<int> counter{0};
  root_ = (fs::temp_directory_path() / ("occlusion-server-test-" + std::to_string(::getpid()) +
                                        "-" + std::to_string(counter++)))
              .string();
  fs::remove_all(root_);
  fs::create_directories(data());
  fs::create_directories(root_ + "/outside");
  std::ofstream(root_ + "/outside/secret.txt") << "1 2 3\n4 5 6\n7 8 9\n";
  const fs::path files = fs::path(OCCLUSION_SOURCE_DIR) / "files";
  fs::copy_file(files / "sample_room.obj", data() + "/sample_room.obj");
  fs::copy(files / "cornell_box", data() + "/cornell_box", fs::copy_options::recursive);
  fs::copy(files / "s3dis_synthetic", data() + "/s3dis_synthetic", fs::copy_options::recursive);
  fs::create_directory_symlink("../outside", data() + "/escape");
}

TestData::~TestData() {
  std::error_code ignored;
  fs::remove_all(root_, ignored);
}

server::ServerOptions TestServer::quiet_options() {
  server::ServerOptions options;
  options.log = [](const std::string&) {};
  options.workers = 2;
  return options;
}

TestServer::TestServer(server::ServerOptions options) {
  options.host = "127.0.0.1";
  options.port = 0;
  options.data_dir = data_.data();
  server_ = std::make_unique<server::Server>(options);
  thread_ = std::thread([this] { server_->run(); });
}

TestServer::~TestServer() {
  server_->stop();
  thread_.join();
}

std::unique_ptr<BlockingClient> TestServer::connect(const std::string& origin) const {
  return std::make_unique<BlockingClient>("127.0.0.1", port(), kHangGuard, origin);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Json::Value run_cli_json(const std::string& arguments, const std::string& directory) {
  const std::string command = (directory.empty() ? "" : "cd '" + directory + "' && ") + "'" +
                              OCCLUSION_CLI_PATH + "' " + arguments + " --json -q 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return Json::Value();
  std::string out;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  ::pclose(pipe);
  Json::Value json;
  std::istringstream stream(out);
  std::string errors;
  if (!Json::parseFromStream(Json::CharReaderBuilder(), stream, &json, &errors))
    return Json::Value();
  return json;
}

Json::Value long_job() {
  return params(R"({"path": "s3dis_synthetic/Area_1/office_1", "point_radius": 0.06,
                    "num_vp": 9, "num_rays_per_vp": 100000000, "out": ""})");
}

std::vector<std::string> work_stages(const Reply& reply) {
  std::vector<std::string> stages;
  for (const Json::Value& event : reply.progress) {
    const std::string stage = event["stage"].asString();
    if (stage != "queued" && stage != "loading") stages.push_back(stage);
  }
  return stages;
}

Json::Value params(const std::string& json) {
  Json::Value value;
  std::istringstream stream(json);
  std::string errors;
  if (!Json::parseFromStream(Json::CharReaderBuilder(), stream, &value, &errors)) {
    ADD_FAILURE() << "bad params literal: " << errors;
  }
  return value;
}

void expect_same_report(const Json::Value& a, const Json::Value& b, const std::string& where) {
  static const std::set<std::string> kSkipped = {
      // Paths differ by where each side runs (data-relative on the server).
      "timings", "input", "outputs", "polygon_path", "ground_truth", "prediction", "mapping_path",
      "predictions", "path", "out", "scenes",
      // The server's own memory and work budgets apply to its jobs (docs/protocol.md).
      "max_memory_mb", "max_work"};
  if (a.isNumeric() && b.isNumeric() && !a.isBool() && !b.isBool()) {
    const double x = a.asDouble(), y = b.asDouble();
    EXPECT_LE(std::abs(x - y), 1e-9 * std::max({1.0, std::abs(x), std::abs(y)}))
        << where << ": server " << x << ", CLI " << y;
    return;
  }
  ASSERT_EQ(a.type(), b.type()) << where;
  if (a.isObject()) {
    // The server adds how to run the same job (`reproduce`) to its result.
    std::vector<std::string> names = a.getMemberNames();
    if (where.empty())
      names.erase(std::remove(names.begin(), names.end(), "reproduce"), names.end());
    EXPECT_EQ(names, b.getMemberNames()) << where;
    for (const auto& key : a.getMemberNames()) {
      if (kSkipped.count(key) > 0 || !b.isMember(key)) continue;
      expect_same_report(a[key], b[key], where + "." + key);
    }
  } else if (a.isArray()) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (Json::ArrayIndex i = 0; i < a.size(); ++i) {
      expect_same_report(a[i], b[i], where + "[" + std::to_string(i) + "]");
    }
  } else {
    EXPECT_EQ(a, b) << where;
  }
}

const std::string* find_frame(const Reply& reply, const std::string& kind, std::uint32_t item) {
  if (!reply.ok()) return nullptr;
  const Json::Value& frames = reply.final["frames"];
  for (Json::ArrayIndex i = 0; i < frames.size() && i < reply.frames.size(); ++i) {
    if (frames[i]["kind"].asString() == kind && frames[i]["item"].asUInt() == item) {
      return &reply.frames[i];
    }
  }
  return nullptr;
}

}  // namespace occlusion::testing
