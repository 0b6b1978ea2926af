#pragma once
// An indexed triangle mesh with named groups (OBJ `g`/`o`), in double precision
// as read from disk. Analyses convert to float triangles for ray casting.

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/core/triangle.hpp"

namespace occlusion {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> faces;
  // face_group[f] indexes group_names; same length as faces.
  std::vector<std::uint32_t> face_group;
  std::vector<std::string> group_names;

  std::size_t face_count() const { return faces.size(); }
  double face_area(std::size_t face) const;
  Triangle triangle(std::size_t face) const;
  std::vector<Triangle> triangles() const;
  // Bounds of the vertices that faces use.
  void bounds(Eigen::Vector3d& lo, Eigen::Vector3d& hi) const;
  // Throws std::invalid_argument on an index out of range, a missing group,
  // a non-finite vertex, or a mismatched face_group size.
  void validate() const;
};

}  // namespace occlusion
