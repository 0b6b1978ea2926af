#pragma once
// A triangle mesh with one value per face, as binary little-endian PLY that
// CloudCompare and MeshLab open directly.
//
// Vertices are not shared: face f owns vertices 3f, 3f+1, 3f+2, so every face
// can carry its own uniform colour. Layout:
//   vertex: float x, y, z; uchar red, green, blue; float scalar_<value_name>;
//           int scalar_group_id
//   face:   list uchar int vertex_indices; float <value_name>; int group_id
// The colour is colour_ramp(value) (viridis, clamped to [0, 1], grey for NaN);
// the value and the group are repeated on the vertices because CloudCompare
// shows vertex properties, not face properties, as scalar fields, and only
// those whose name contains "scalar" (it shows scalar_<name> as "<name>"). The header has one
// `comment group <id> <name>` line per group of the mesh.

#include <string>
#include <vector>

#include "occlusion/core/mesh.hpp"

namespace occlusion {

// Throws std::invalid_argument if face_values.size() != mesh.face_count(), the
// mesh is invalid, or value_name is not a plain identifier distinct from the
// other property names; OutputError if the file cannot be written. Written
// atomically (atomic_file.hpp).
void write_mesh_ply(const std::string& path, const TriangleMesh& mesh,
                    const std::vector<float>& face_values, const std::string& value_name);

}  // namespace occlusion
