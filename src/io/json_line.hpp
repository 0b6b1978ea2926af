#pragma once
// Where a parsed JSON value stands in its text, so that an error in a file
// the user wrote (a frame descriptor, a project) names the line to fix.

#include <json/value.h>

#include <algorithm>
#include <cstddef>
#include <string_view>

namespace occlusion::detail {

// The 1-based line where `value` starts in `text`, the text it was parsed from.
inline std::size_t json_line(std::string_view text, const Json::Value& value) {
  const auto offset = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, value.getOffsetStart()));
  const auto end = text.begin() + static_cast<std::ptrdiff_t>(std::min(offset, text.size()));
  return 1 + static_cast<std::size_t>(std::count(text.begin(), end, '\n'));
}

}  // namespace occlusion::detail
