#pragma once
// The JSON text messages of docs/protocol.md: reading a request, writing
// hello, progress, result and error messages.

#include <json/value.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "occlusion/server/binary_frame.hpp"

namespace occlusion::server {

constexpr int kProtocolVersion = 1;

struct Request {
  std::uint32_t id = 0;
  std::string command;
  Json::Value params{Json::objectValue};
};

// Throws ProtocolError "invalid_json" for text that is not one JSON value.
Json::Value parse_json(std::string_view text);
// Throws ProtocolError "invalid_request" for anything but
// {"id": uint32, "command": string, "params": object (optional)}.
Request read_request(const Json::Value& message);
// The id to name in an error about `message`: its id if it is a valid one, else null.
Json::Value request_id_of(const Json::Value& message);

// Compact JSON, numbers with 17 significant digits (they read back exactly).
std::string write_json(const Json::Value& value);

std::string result_message(std::uint32_t id, const std::string& command, Json::Value result,
                           const std::vector<FrameHeader>& frames);
std::string error_message(const Json::Value& id, const std::string& command,
                          const std::string& code, const std::string& message);
std::string progress_message(std::uint32_t id, const std::string& stage, double fraction);
// A waiting request's progress: stage "queued", fraction 0, and
// "queue_position", the number of requests that start before it.
std::string queued_message(std::uint32_t id, std::size_t ahead);

}  // namespace occlusion::server
