#include "arguments.hpp"

#include <charconv>
#include <cmath>

#include "occlusion/app/errors.hpp"

namespace occlusion::cli {

double parse_number(const std::string& option, const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw UsageError(option + " expects a number, got '" + text + "'");
  }
  return value;
}

std::uint64_t parse_unsigned(const std::string& option, const std::string& text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) {
    throw UsageError(option + " expects a non-negative integer, got '" + text + "'");
  }
  return value;
}

bool parse_bool(const std::string& option, const std::string& text) {
  if (text == "true" || text == "1" || text == "on" || text == "yes") return true;
  if (text == "false" || text == "0" || text == "off" || text == "no") return false;
  throw UsageError(option + " expects true or false, got '" + text + "'");
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    if (comma > start) items.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return items;
}

Eigen::Vector3d parse_point(const std::string& option, const std::string& text) {
  Eigen::Vector3d point;
  std::size_t start = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t comma = text.find(',', start);
    const bool last = axis == 2;
    if (last != (comma == std::string::npos)) {
      throw UsageError(option + " expects X,Y,Z, got '" + text + "'");
    }
    const std::string part = text.substr(start, last ? std::string::npos : comma - start);
    point[axis] = parse_number(option, part);
    start = comma + 1;
  }
  return point;
}

}  // namespace occlusion::cli
