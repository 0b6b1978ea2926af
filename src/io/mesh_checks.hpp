#pragma once
// Checks every mesh reader makes on what it read, so that OBJ and PLY meshes
// are treated alike: a triangle with no area is hit by no ray and has nothing
// to sample, so it is dropped and counted rather than refusing the mesh.

#include <cstddef>
#include <functional>
#include <string>

#include "occlusion/core/mesh.hpp"
#include "occlusion/io/mesh_read_report.hpp"

namespace occlusion::detail {

// Removes every triangle that repeats a vertex or whose area is at most 1e-12
// times the squared diagonal of the bounding box of the used vertices (so the
// test does not depend on units), with its face_group entry; a group left
// without faces is removed and the others renumbered in order, so groups
// still appear only when they have faces. Counts them in `report`;
// `where(f)` names triangle f (its index before removal) in the file, e.g.
// "line 12", for the first one's description. Vertex numbers count from
// `first_vertex_number` (OBJ 1, PLY 0). The mesh must have a face_group entry
// per face. InputError naming `path` when no face is left.
void drop_degenerate_faces(TriangleMesh& mesh, std::size_t first_vertex_number,
                           const std::function<std::string(std::size_t)>& where,
                           const std::string& path, MeshReadReport& report);

}  // namespace occlusion::detail
