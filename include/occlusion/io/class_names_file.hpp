#pragma once
// A class_names file: the names of a cloud's integer labels, for clouds that
// do not name them (a PLY or PCD with a bare `label` field, a text cloud).
// One name per line, line k (counting from 0) naming label k:
//
//   ceiling
//   floor
//   wall
//
// A name is the line without surrounding spaces and tabs; inner spaces are
// kept ("shower curtain"). A blank line before a name is an error, since it
// would shift every later name onto the wrong label (blank lines at the end
// are fine), and so is a name given twice. Line ends LF, CR LF or CR; a UTF-8
// byte-order mark is skipped.

#include <string>
#include <string_view>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

// InputError naming the file and line for a blank line or a repeated name,
// and for a file with no names.
std::vector<std::string> read_class_names_file(const std::string& path);
// The same from text in memory; `source` names it in errors.
std::vector<std::string> parse_class_names(std::string_view text, const std::string& source);

// Gives `cloud` (read from `cloud_name`) the names of `names_path`.
// InputError naming the names file for a label it does not name, or naming
// the cloud when it has no labels, or names of its own that differ (the
// file would contradict what the cloud says its labels mean).
void apply_class_names_file(PointCloud& cloud, const std::string& cloud_name,
                            const std::string& names_path);

}  // namespace occlusion
