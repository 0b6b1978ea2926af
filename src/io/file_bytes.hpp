#pragma once
// Whole files in memory: the readers parse from a buffer, so that truncation
// is a length comparison, a byte offset is an index and a line is a view.

#include <string>

namespace occlusion::detail {

// The file's bytes. InputError if it is a directory, missing or unreadable.
std::string read_file_bytes(const std::string& path);

}  // namespace occlusion::detail
