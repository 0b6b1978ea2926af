#pragma once
// Reading option values from the command line. Every parse error is a
// UsageError that names the option.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion::cli {

double parse_number(const std::string& option, const std::string& text);
std::uint64_t parse_unsigned(const std::string& option, const std::string& text);
bool parse_bool(const std::string& option, const std::string& text);
// "a,b,c" -> {"a", "b", "c"}; empty items are dropped.
std::vector<std::string> split_list(const std::string& text);

// "X,Y,Z"
Eigen::Vector3d parse_point(const std::string& option, const std::string& text);

}  // namespace occlusion::cli
