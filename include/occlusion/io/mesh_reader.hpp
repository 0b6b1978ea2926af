#pragma once
// Triangle meshes from disk, by extension: `.obj` (obj_reader.hpp) or `.ply`;
// or a ScanNet scene (docs/formats.md: a scene folder, its labels file, or its
// mesh with the labels file beside it), whose faces are grouped by the NYU40
// class at least two of their corners share ("mixed" when none is shared).
//
// PLY (ascii or binary, either byte order): element `vertex` with float or
// double x y z (other vertex properties ignored), element `face` with an
// integer list property `vertex_indices` (or `vertex_index`), 0-based.
// Polygons are fan-triangulated as in OBJ. An integer face property
// `group_id` puts each face in a group, named by `comment group <id> <name>`
// header lines (as write_mesh_ply writes them; unnamed ids become "group <id>");
// without it every face is in group "default". So the meshes -rgoc writes
// (ply_mesh_writer.hpp) can be measured again with -moc.
//
// Degenerate triangles (no area) are dropped and counted in `report`, as the
// OBJ reader does. InputError naming the file for what the OBJ reader refuses
// too (an index out of range, a face with fewer than 3 corners, no faces or
// none with an area, a non-finite coordinate), with the line (ascii) or byte
// offset, and for a PLY without a vertex element, x y z, or a face index list.
// An extension other than .obj or .ply is an InputError saying which are read.

#include <string>
#include <vector>

#include "occlusion/core/mesh.hpp"
#include "occlusion/io/mesh_read_report.hpp"

namespace occlusion {

TriangleMesh read_mesh(const std::string& path, MeshReadReport* report = nullptr);
// The file name endings read_mesh reads, lower case with their dot (".obj").
const std::vector<std::string>& mesh_file_suffixes();
// Whether read_mesh reads `path` by its name (any letter case; ScanNet folders aside).
bool is_mesh_file(const std::string& path);
// Whether `path` holds a mesh rather than a cloud: an OBJ (or a ScanNet
// scene's mesh by its name), or a PLY whose header declares at least one face
// (a PLY of points is a cloud). Reads at most the header; false when the
// header cannot be read, so that the cloud reader says why.
bool holds_mesh(const std::string& path);
TriangleMesh read_ply_mesh(const std::string& path, MeshReadReport* report = nullptr);

}  // namespace occlusion
