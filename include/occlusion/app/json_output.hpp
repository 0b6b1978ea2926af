#pragma once
// Small helpers shared by every job's report.

#include <json/value.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "occlusion/core/octree.hpp"

namespace occlusion {

Json::Value to_json(const Eigen::Vector3d& point);
Json::Value to_json(const std::vector<std::string>& strings);
// {"inner_nodes", "leaves", "depth", "largest_leaf", "memory_bytes"}
Json::Value to_json(const OctreeStats& stats);
// null when absent: an undefined figure (an mIoU without classes) is not 0.
Json::Value to_json(const std::optional<double>& value);
// `text` with every byte that is not part of well-formed UTF-8 replaced by
// U+FFFD. File names are bytes on Linux; JSON must be UTF-8.
std::string valid_utf8(std::string_view text);
// valid_utf8, and every control character (C0 but tab, DEL, C1) replaced by
// U+FFFD too: text from another program (a segmenter's output) that goes into
// a CSV cell or a Markdown table, where a stray escape or NUL byte would
// corrupt the file for every reader.
std::string printable_text(std::string_view text);
// The value with valid_utf8 applied to every string and key.
Json::Value with_valid_utf8(const Json::Value& value);
// Indented, 15 significant digits, UTF-8 kept as is and invalid UTF-8
// replaced (with_valid_utf8), so the text is always valid JSON.
std::string format_json(const Json::Value& value);

}  // namespace occlusion
