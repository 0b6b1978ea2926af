#include "command_params.hpp"

#include <algorithm>
#include <cmath>

#include "occlusion/server/protocol_error.hpp"

namespace occlusion::server {

namespace {

[[noreturn]] void fail(const std::string& message) {
  throw ProtocolError("invalid_request", message);
}

}  // namespace

void allow_keys(const Json::Value& params, const std::vector<std::string>& keys) {
  for (const auto& key : params.getMemberNames()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string known;
      for (const auto& k : keys) known += (known.empty() ? "" : ", ") + k;
      fail("unknown parameter '" + key + "' (known: " + known + ")");
    }
  }
}

std::string string_param(const Json::Value& params, const std::string& key,
                         const std::string& fallback) {
  if (!params.isMember(key)) return fallback;
  if (!params[key].isString()) fail("'" + key + "' must be a string");
  return params[key].asString();
}

std::string required_string(const Json::Value& params, const std::string& key) {
  if (!params.isMember(key)) fail("missing parameter '" + key + "'");
  return string_param(params, key, "");
}

bool bool_param(const Json::Value& params, const std::string& key, bool fallback) {
  if (!params.isMember(key)) return fallback;
  if (!params[key].isBool()) fail("'" + key + "' must be true or false");
  return params[key].asBool();
}

std::uint64_t required_unsigned(const Json::Value& params, const std::string& key) {
  if (!params.isMember(key)) fail("missing parameter '" + key + "'");
  const Json::Value& value = params[key];
  if (value.isBool() || !value.isUInt64()) fail("'" + key + "' must be a non-negative integer");
  return value.asUInt64();
}

std::array<double, 3> required_point(const Json::Value& params, const std::string& key) {
  if (!params.isMember(key)) fail("missing parameter '" + key + "'");
  const Json::Value& value = params[key];
  std::array<double, 3> point{};
  if (!value.isArray() || value.size() != 3) fail("'" + key + "' must be [x, y, z]");
  for (Json::ArrayIndex a = 0; a < 3; ++a) {
    if (value[a].isBool() || !value[a].isNumeric() || !std::isfinite(value[a].asDouble())) {
      fail("'" + key + "' must be [x, y, z], three finite numbers");
    }
    point[a] = value[a].asDouble();
  }
  return point;
}

}  // namespace occlusion::server
