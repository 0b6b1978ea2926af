#include "occlusion/core/mesh.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace occlusion {

double TriangleMesh::face_area(std::size_t face) const {
  const auto& f = faces[face];
  const Eigen::Vector3d& a = vertices[f[0]];
  return 0.5 * (vertices[f[1]] - a).cross(vertices[f[2]] - a).norm();
}

Triangle TriangleMesh::triangle(std::size_t face) const {
  const auto& f = faces[face];
  return {vertices[f[0]].cast<float>(), vertices[f[1]].cast<float>(), vertices[f[2]].cast<float>()};
}

std::vector<Triangle> TriangleMesh::triangles() const {
  std::vector<Triangle> out;
  out.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) out.push_back(triangle(f));
  return out;
}

void TriangleMesh::bounds(Eigen::Vector3d& lo, Eigen::Vector3d& hi) const {
  lo.setConstant(std::numeric_limits<double>::infinity());
  hi.setConstant(-std::numeric_limits<double>::infinity());
  for (const auto& f : faces) {
    for (const std::uint32_t v : f) {
      lo = lo.cwiseMin(vertices[v]);
      hi = hi.cwiseMax(vertices[v]);
    }
  }
}

void TriangleMesh::validate() const {
  if (face_group.size() != faces.size()) {
    throw std::invalid_argument("mesh: face_group has " + std::to_string(face_group.size()) +
                                " entries for " + std::to_string(faces.size()) + " faces");
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (const std::uint32_t v : faces[f]) {
      if (v >= vertices.size()) {
        throw std::invalid_argument("mesh: face " + std::to_string(f) + " uses vertex " +
                                    std::to_string(v) + " of " + std::to_string(vertices.size()));
      }
      if (!vertices[v].allFinite()) {
        throw std::invalid_argument("mesh: vertex " + std::to_string(v) + " is not finite");
      }
    }
    if (face_group[f] >= group_names.size()) {
      throw std::invalid_argument("mesh: face " + std::to_string(f) + " has group " +
                                  std::to_string(face_group[f]) + " of " +
                                  std::to_string(group_names.size()));
    }
  }
}

}  // namespace occlusion
