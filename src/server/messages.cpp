#include "messages.hpp"

#include <json/writer.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "occlusion/io/strict_json.hpp"
#include "occlusion/server/protocol_error.hpp"

namespace occlusion::server {

namespace {

bool valid_id(const Json::Value& id) {
  // isUInt() also accepts 3.0; a bool is never an id.
  return !id.isBool() && id.isUInt();
}

}  // namespace

Json::Value parse_json(std::string_view text) {
  Json::Value value;
  std::string errors;
  // Deep nesting is refused, not recursed into.
  if (!parse_strict_json(text, StrictJson{256, false}, value, errors)) {
    throw ProtocolError("invalid_json", "message is not valid JSON: " + errors);
  }
  return value;
}

Request read_request(const Json::Value& message) {
  const auto fail = [](const std::string& why) { throw ProtocolError("invalid_request", why); };
  if (!message.isObject()) fail("a request must be a JSON object");
  if (!message.isMember("id")) fail("a request needs an 'id'");
  if (!valid_id(message["id"])) fail("'id' must be an integer in 0..4294967295");
  if (!message.isMember("command") || !message["command"].isString()) {
    fail("a request needs a 'command' string");
  }
  for (const auto& key : message.getMemberNames()) {
    if (key != "id" && key != "command" && key != "params") {
      fail("unknown key '" + key + "' in the request (id, command, params)");
    }
  }
  Request request;
  request.id = message["id"].asUInt();
  request.command = message["command"].asString();
  if (message.isMember("params")) {
    if (!message["params"].isObject()) fail("'params' must be an object");
    request.params = message["params"];
  }
  return request;
}

Json::Value request_id_of(const Json::Value& message) {
  if (message.isObject() && message.isMember("id") && valid_id(message["id"])) {
    return message["id"];
  }
  return Json::Value();
}

std::string write_json(const Json::Value& value) {
  static const Json::StreamWriterBuilder builder = [] {
    Json::StreamWriterBuilder b;
    b["indentation"] = "";
    b["precision"] = 17;
    return b;
  }();
  return Json::writeString(builder, value);
}

std::string result_message(std::uint32_t id, const std::string& command, Json::Value result,
                           const std::vector<FrameHeader>& frames) {
  Json::Value message(Json::objectValue);
  message["type"] = "result";
  message["id"] = id;
  message["command"] = command;
  message["result"] = std::move(result);
  Json::Value list(Json::arrayValue);
  for (const auto& frame : frames) list.append(describe(frame));
  message["frames"] = list;
  return write_json(message);
}

std::string error_message(const Json::Value& id, const std::string& command,
                          const std::string& code, const std::string& message) {
  Json::Value json(Json::objectValue);
  json["type"] = "error";
  json["id"] = id;
  if (!command.empty()) json["command"] = command;
  json["code"] = code;
  json["message"] = message;
  return write_json(json);
}

std::string queued_message(std::uint32_t id, std::size_t ahead) {
  Json::Value json(Json::objectValue);
  json["type"] = "progress";
  json["id"] = id;
  json["stage"] = "queued";
  json["fraction"] = 0.0;
  json["queue_position"] = Json::UInt64(ahead);
  return write_json(json);
}

std::string progress_message(std::uint32_t id, const std::string& stage, double fraction) {
  Json::Value json(Json::objectValue);
  json["type"] = "progress";
  json["id"] = id;
  json["stage"] = stage;
  json["fraction"] = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  return write_json(json);
}

}  // namespace occlusion::server
