#pragma once
// Is a viewpoint inside a closed solid of a mesh (a column, a cupboard
// modelled as a box)? From inside one, the rays of a light source hit the
// inside of its faces, i.e. their back (the side their normal, e1 x e2 in the
// file's vertex order, points away from), and the occlusion level measures
// the inside of that solid. A mesh whose faces all point away from the room
// looks the same from inside the room, so the warning the jobs print names both
// causes.

#include <Eigen/Core>
#include <vector>

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

// Rays per viewpoint (a Fibonacci lattice, no seed needed), and the share of
// them whose first hit is a back face above which a viewpoint is taken to be
// inside a solid.
inline constexpr std::size_t kInsideProbeRays = 256;
inline constexpr double kInsideBackFaceShare = 0.5;

// Per viewpoint: back-face first hits over all kInsideProbeRays rays.
// std::invalid_argument for a mesh without faces or a non-finite viewpoint.
std::vector<double> back_face_shares(const TriangleMesh& mesh,
                                     const std::vector<Eigen::Vector3d>& viewpoints);

// The same over a tree already built on the mesh's triangles, viewpoints in
// the tree's frame: compute_mesh_occlusion's own, so that the jobs' warning
// costs no second tree. std::invalid_argument for a non-finite viewpoint.
std::vector<double> back_face_shares(const TriangleOctree& tree,
                                     const std::vector<Eigen::Vector3d>& viewpoints);

}  // namespace occlusion
