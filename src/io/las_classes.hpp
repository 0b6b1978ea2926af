#pragma once
// The ASPRS standard point classes a LAS classification means.

#include <string>

namespace occlusion::detail {

// The name of class `id` (0..255) in a LAS 1.<version_minor> file: the
// standard classes of that version's table (LAS 1.4 R15 table 17; before
// 1.4, 8 was "model_key_point" and 12 "overlap", and 10, 11 and 13..31 were
// reserved), "reserved_<id>" for ids the standard keeps, "user_<id>" for
// the user-definable ids 64..255.
std::string las_class_name(int id, int version_minor);

}  // namespace occlusion::detail
