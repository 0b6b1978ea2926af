#pragma once
// What a file's name says about it; the readers choose by extension in any
// letter case.

#include <string>

namespace occlusion::detail {

// The extension with its dot, lower-cased: "scan.PCD" -> ".pcd", "room" -> "".
std::string lower_extension(const std::string& path);
// Whether the file name ends with `suffix` (lower case, e.g. ".frame.json")
// in any letter case.
bool has_lower_suffix(const std::string& path, const std::string& suffix);

}  // namespace occlusion::detail
