#pragma once
// A small blocking WebSocket client for the protocol of docs/protocol.md: the
// server's tests, the load benchmark and scripts use it. Every wait has a
// timeout, so a server bug shows up as a failure, never as a hang.

#include <json/value.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace occlusion::server {

struct ClientMessage {
  bool binary = false;
  std::string data;
};

// Everything a request got back: its progress events, binary frames (whole
// messages, header included) and the final result or error message.
struct Reply {
  Json::Value final;  // {"type": "result" | "error", ...}; null after a timeout
  std::vector<Json::Value> progress;
  std::vector<std::string> frames;

  bool ok() const { return final.isObject() && final["type"].asString() == "result"; }
  std::string error_code() const { return final.isObject() ? final["code"].asString() : ""; }
};

class BlockingClient {
 public:
  using Duration = std::chrono::milliseconds;

  // Connects to ws://host:port/ws and waits for the hello message. `origin`,
  // when not empty, is sent as the Origin header. Throws std::runtime_error
  // when the connection fails or times out.
  BlockingClient(const std::string& host, std::uint16_t port, Duration timeout = Duration(10000),
                 const std::string& origin = "");
  ~BlockingClient();
  BlockingClient(const BlockingClient&) = delete;
  BlockingClient& operator=(const BlockingClient&) = delete;

  const Json::Value& hello() const;

  void send_text(const std::string& text);
  void send_binary(std::string message);
  void send_request(std::uint32_t id, const std::string& command,
                    const Json::Value& params = Json::Value(Json::objectValue));

  // The next message not yet taken; nullopt after the timeout or once closed.
  std::optional<ClientMessage> receive(Duration timeout);
  // The messages of request `id` up to its result or error; messages of other
  // requests stay queued for later calls.
  Reply collect(std::uint32_t id, Duration timeout);
  // send_request + collect.
  Reply request(std::uint32_t id, const std::string& command,
                const Json::Value& params = Json::Value(Json::objectValue),
                Duration timeout = Duration(60000));

  // The server closed the connection (waits up to `timeout` for it).
  bool wait_closed(Duration timeout);
  // The close code the server sent (1009: message too big), 0 if none yet.
  int close_code() const;
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The request id in a binary message's header (0 for a malformed one).
std::uint32_t frame_request_id(const std::string& message);

}  // namespace occlusion::server
