#pragma once
// A real server on 127.0.0.1 and an ephemeral port, in this process, over a
// fresh copy of the sample scenes; clients connect to it with real sockets.

#include <json/value.h>
#include <json/writer.h>  // operator<< for failure messages

#include <chrono>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "occlusion/server/binary_frame.hpp"
#include "occlusion/server/blocking_client.hpp"
#include "occlusion/server/server.hpp"

namespace occlusion::testing {

using server::BlockingClient;
using server::Reply;
using Millis = std::chrono::milliseconds;

// ROOT/data holds sample_room.obj, cornell_box/ and s3dis_synthetic/;
// ROOT/outside/secret.txt is outside it and ROOT/data/escape links to ROOT/outside.
class TestData {
 public:
  TestData();
  ~TestData();
  TestData(const TestData&) = delete;
  TestData& operator=(const TestData&) = delete;
  const std::string& root() const { return root_; }
  std::string data() const { return root_ + "/data"; }
  std::string file(const std::string& relative) const { return data() + "/" + relative; }

 private:
  std::string root_;
};

class TestServer {
 public:
  // options.data_dir and options.port are filled in; the rest is kept.
  explicit TestServer(server::ServerOptions options = quiet_options());
  ~TestServer();

  static server::ServerOptions quiet_options();

  std::uint16_t port() const { return server_->port(); }
  const TestData& files() const { return data_; }
  std::unique_ptr<BlockingClient> connect(const std::string& origin = "") const;

 private:
  TestData data_;
  std::unique_ptr<server::Server> server_;
  std::thread thread_;
};

// Runs the built CLI with `arguments` (shell words), in `directory` when one
// is given; its stdout parsed as JSON (null if it is not).
Json::Value run_cli_json(const std::string& arguments, const std::string& directory = "");

// Params object from a JSON literal, e.g. params(R"({"path": "x"})").
Json::Value params(const std::string& json);

// How long a test waits for a message that must come before it calls the
// server hung. It bounds a wait; it is never the figure a test asserts, so a
// slow or loaded machine only waits longer.
inline constexpr Millis kHangGuard{180000};

// A cloud_occlusion job that runs for minutes unless cancelled (9 x 1e8 rays:
// about 4 minutes on 2 threads in Release), in little memory: rays are traced
// in blocks, and no escape directions are kept without "out". A test that
// sees it end "cancelled" knows it was still running.
Json::Value long_job();

// The stages of a reply's progress events that do the job's work: every
// stage but "queued" and "loading" (a refusal up front reports none).
std::vector<std::string> work_stages(const Reply& reply);

// Compares a job's figures in the server's reply to the CLI's report: every
// key of both, numbers to 1e-9 relative, except timings and file names (the
// two name the same files differently).
void expect_same_report(const Json::Value& server_json, const Json::Value& cli_json,
                        const std::string& where = "");

// The payload of a binary frame as values of T (empty if the sizes disagree).
template <class T>
std::vector<T> frame_values(const std::string& message) {
  const auto header = server::decode_frame_header(message);
  std::vector<T> values(header.count * header.components);
  if (header.payload_bytes() != values.size() * sizeof(T)) return {};
  if (!values.empty()) {
    std::memcpy(values.data(), message.data() + server::kFrameHeaderSize, header.payload_bytes());
  }
  return values;
}

// The frame of `kind` among a reply's frames, or nullptr.
const std::string* find_frame(const Reply& reply, const std::string& kind, std::uint32_t item = 0);

std::string read_file(const std::string& path);

}  // namespace occlusion::testing
