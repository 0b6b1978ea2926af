#pragma once
// Small helpers shared by every job's report.

#include <json/value.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace occlusion {

Json::Value to_json(const Eigen::Vector3d& point);
Json::Value to_json(const std::vector<std::string>& strings);
// Indented, 15 significant digits, UTF-8 kept as is.
std::string format_json(const Json::Value& value);
// A CSV field, quoted when it holds a comma, quote or newline (RFC 4180).
std::string csv_field(const std::string& text);

}  // namespace occlusion
