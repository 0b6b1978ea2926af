#pragma once
// Meshes whose occlusion is known exactly, built in code.

#include <Eigen/Core>
#include <string>

#include "occlusion/core/mesh.hpp"

namespace occlusion::testing {

// Adds an axis-aligned rectangle as two triangles: corner + s*edge_a + t*edge_b.
void add_quad(TriangleMesh& mesh, const Eigen::Vector3d& corner, const Eigen::Vector3d& edge_a,
              const Eigen::Vector3d& edge_b, const std::string& group);

// The six faces of the box [lo, hi], each face split into n x n quads.
void add_box(TriangleMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
             const std::string& group, int n = 1);

}  // namespace occlusion::testing
