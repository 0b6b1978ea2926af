#pragma once
// A TriangleMesh as Wavefront OBJ, the format read_obj reads back.
//
// `v` lines carry the shortest decimal that reads back as the same double, so
// the file holds exactly the mesh in memory; `f` lines use 1-based indices, and
// a `g <group name>` line starts each run of faces of one group (groups without
// faces do not appear, as read_obj would drop them). Line breaks and tabs in a
// group name become spaces. `comment`, when not empty, becomes leading `#` lines.

#include <string>

#include "occlusion/core/mesh.hpp"

namespace occlusion {

// std::invalid_argument for an invalid mesh (TriangleMesh::validate);
// OutputError if the file cannot be written. Written atomically (atomic_file.hpp).
void write_obj(const std::string& path, const TriangleMesh& mesh, const std::string& comment = "");

}  // namespace occlusion
