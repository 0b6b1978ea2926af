#pragma once
// Wavefront OBJ reader for triangle meshes.
//
// Reads `v x y z [w ...]` (anything after x y z, such as w or a vertex colour,
// is ignored), `f` with `i`, `i/t`, `i/t/n` or `i//n` corners and 1-based or
// negative (relative) indices, and `g`/`o` groups. Polygons are fan-triangulated
// as (v0, vi, vi+1). Faces before any `g`/`o` belong to group "default"; a group
// appears in group_names only if it has faces, in order of its first face.
// Texture coordinates, normals, materials, lines, points, smoothing groups,
// comments and statements this reader does not know are skipped: OBJ has many
// extensions, and none of them changes the geometry we measure.
// CRLF, blank lines, leading whitespace and `\` line continuation are accepted.
//
// Everything else is an InputError naming the file and the 1-based line: an index
// that is 0 or out of range, a missing, non-numeric or non-finite coordinate, a
// face with fewer than 3 corners, and a file with no faces, or none with an
// area. A degenerate triangle (a repeated vertex, or area <= 1e-12 * squared
// diagonal of the bounding box of the face vertices) is dropped and counted in
// `report` (mesh_read_report.hpp): it has no area and no ray hits it.

#include <string>
#include <string_view>

#include "occlusion/core/mesh.hpp"
#include "occlusion/io/mesh_read_report.hpp"

namespace occlusion {

// read_mesh (mesh_reader.hpp) chooses this or the PLY reader by extension.
TriangleMesh read_obj(const std::string& path, MeshReadReport* report = nullptr);

// Parses OBJ text; `source_name` is only used in error messages.
TriangleMesh parse_obj(std::string_view text, const std::string& source_name,
                       MeshReadReport* report = nullptr);

}  // namespace occlusion
