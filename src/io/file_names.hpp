#pragma once
// What a file's name says about it; the readers choose by extension in any
// letter case.

#include <string>

namespace occlusion::detail {

// The extension with its dot, lower-cased: "scan.PCD" -> ".pcd", "room" -> "".
std::string lower_extension(const std::string& path);
// Whether the file name of `path` ends in `suffix` (lower case, with its dot),
// in any letter case: "Frame.E57" ends in ".e57". A suffix may hold several
// dots, which an extension cannot.
bool has_suffix(const std::string& path, const std::string& suffix);

}  // namespace occlusion::detail
