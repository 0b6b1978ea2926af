#pragma once
// A deterministic synthetic scene for benchmarks and demos: a furnished room.
//
// The room is a closed box of kRoomSize metres (x east, y north, z up) with
// floor, ceiling and four walls, furnished with tables and chairs, bookcases
// with books, a sofa, floor lamps, potted plants and vases. Every piece is one
// OBJ group (table_1, chair_3, bookcase_2, ...). The seed decides sizes and
// placement; pieces keep clear of the walls, of each other, and of the
// vertical lines through the pattern viewpoints (viewpoints.hpp), so that no
// viewpoint ends up inside furniture.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>

#include "occlusion/core/mesh.hpp"

namespace occlusion::bench {

inline const Eigen::Vector3d kRoomSize{8.0, 6.0, 3.0};

struct GeneratedRoom {
  TriangleMesh mesh;
  double density = 0.0;  // grid cells per metre the tessellation settled on
};

// The room with the smallest tessellation density whose triangle count is at
// least `target_triangles` (a few percent above it at most). A target below
// what the furniture needs at its coarsest gives that coarsest room.
// Throws std::invalid_argument for a target above 50 million.
GeneratedRoom generate_room(std::size_t target_triangles, std::uint64_t seed);

}  // namespace occlusion::bench
