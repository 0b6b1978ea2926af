#pragma once
// Checks every mesh reader makes on what it read, so that OBJ and PLY meshes
// are refused for the same reasons: a triangle with no area would be hit by
// no ray and silently change the occlusion result.

#include <cstddef>
#include <optional>
#include <string>

#include "occlusion/core/mesh.hpp"

namespace occlusion::detail {

struct DegenerateFace {
  std::size_t face = 0;  // the triangle's index in mesh.faces
  std::string reason;    // "degenerate face (zero area): ..."
};

// The first triangle that repeats a vertex or whose area is at most 1e-12 times
// the squared diagonal of the bounding box of the used vertices (so the test
// does not depend on units). Vertex numbers in the reason count from
// `first_vertex_number` (OBJ 1, PLY 0).
std::optional<DegenerateFace> find_degenerate_face(const TriangleMesh& mesh,
                                                   std::size_t first_vertex_number);

}  // namespace occlusion::detail
