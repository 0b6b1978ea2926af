#pragma once
// Typed reads of the params of the server's own commands (list_files, load,
// upload, save_polygon, cancel). Job params are config keys instead
// (job_params.hpp). Each failure is ProtocolError "invalid_request" naming the key.

#include <json/value.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion::server {

void allow_keys(const Json::Value& params, const std::vector<std::string>& keys);
std::string string_param(const Json::Value& params, const std::string& key,
                         const std::string& fallback);
std::string required_string(const Json::Value& params, const std::string& key);
bool bool_param(const Json::Value& params, const std::string& key, bool fallback);
std::uint64_t required_unsigned(const Json::Value& params, const std::string& key);
// [x, y, z], three finite numbers.
std::array<double, 3> required_point(const Json::Value& params, const std::string& key);

}  // namespace occlusion::server
