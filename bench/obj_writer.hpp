#pragma once
// Writes a TriangleMesh as Wavefront OBJ, the format `occlusion -moc` reads.

#include <string>

#include "occlusion/core/mesh.hpp"

namespace occlusion::bench {

// `v` lines carry the shortest decimal that reads back as the same double, so
// the file holds exactly the mesh in memory; `f` lines use 1-based indices and
// a `g` line starts each run of faces of one group. `comment` (may be empty)
// becomes a leading `#` line. Throws std::runtime_error naming the path if the
// file cannot be written.
void write_obj(const TriangleMesh& mesh, const std::string& path, const std::string& comment = "");

}  // namespace occlusion::bench
