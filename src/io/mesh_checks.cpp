#include "mesh_checks.hpp"

#include <limits>

namespace occlusion::detail {

namespace {
constexpr double kDegenerateAreaScale = 1e-12;
}  // namespace

std::optional<DegenerateFace> find_degenerate_face(const TriangleMesh& mesh,
                                                   std::size_t first_vertex_number) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto& face : mesh.faces) {
    for (const std::uint32_t index : face) {
      lo = lo.cwiseMin(mesh.vertices[index]);
      hi = hi.cwiseMax(mesh.vertices[index]);
    }
  }
  const auto number = [&](std::uint32_t index) {
    return std::to_string(std::size_t{index} + first_vertex_number);
  };
  const double min_area = kDegenerateAreaScale * (hi - lo).squaredNorm();
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& [a, b, c] = mesh.faces[f];
    if (a == b || b == c || a == c) {
      const std::uint32_t repeated = (a == b || a == c) ? a : b;
      return DegenerateFace{f, "degenerate face (zero area): vertex " + number(repeated) +
                                   " is used twice in one triangle"};
    }
    const Eigen::Vector3d& p = mesh.vertices[a];
    const double area = 0.5 * (mesh.vertices[b] - p).cross(mesh.vertices[c] - p).norm();
    if (area <= min_area) {
      return DegenerateFace{f, "degenerate face (zero area): vertices " + number(a) + ", " +
                                   number(b) + ", " + number(c) + " are collinear"};
    }
  }
  return std::nullopt;
}

}  // namespace occlusion::detail
