#pragma once
// What the mesh readers (mesh_reader.hpp, obj_reader.hpp) left out of a mesh
// they accepted, for the jobs to report.

#include <cstddef>
#include <string>

namespace occlusion {

struct MeshReadReport {
  // Triangles of no area (a vertex used twice, or area at most 1e-12 x the
  // squared diagonal of the used vertices' box) skipped. Reconstructed meshes
  // hold a few (ScanNet's, Poisson's): no ray can hit one and it has no area to
  // sample, so leaving it out changes no figure, and refusing the whole mesh
  // for it helped nobody.
  std::size_t degenerate_faces = 0;
  // The first one, as "line 12: degenerate face (zero area): ..." (OBJ) or
  // "face 7: ..." (PLY); empty when none was skipped.
  std::string first_degenerate;
};

}  // namespace occlusion
