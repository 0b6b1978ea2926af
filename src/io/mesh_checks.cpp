#include "mesh_checks.hpp"

#include "occlusion/io/input_error.hpp"

#include <limits>
#include <optional>
#include <vector>

namespace occlusion::detail {

namespace {

constexpr double kDegenerateAreaScale = 1e-12;

// Why triangle f has no area, or nothing when it has some.
std::optional<std::string> degenerate_reason(const TriangleMesh& mesh, std::size_t f,
                                             double min_area, std::size_t first_vertex_number) {
  const auto number = [&](std::uint32_t index) {
    return std::to_string(std::size_t{index} + first_vertex_number);
  };
  const auto& [a, b, c] = mesh.faces[f];
  if (a == b || b == c || a == c) {
    const std::uint32_t repeated = (a == b || a == c) ? a : b;
    return "degenerate face (zero area): vertex " + number(repeated) +
           " is used twice in one triangle";
  }
  const Eigen::Vector3d& p = mesh.vertices[a];
  const double area = 0.5 * (mesh.vertices[b] - p).cross(mesh.vertices[c] - p).norm();
  if (area > min_area) return std::nullopt;
  return "degenerate face (zero area): vertices " + number(a) + ", " + number(b) + ", " +
         number(c) + " are collinear";
}

}  // namespace

void drop_degenerate_faces(TriangleMesh& mesh, std::size_t first_vertex_number,
                           const std::function<std::string(std::size_t)>& where,
                           const std::string& path, MeshReadReport& report) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto& face : mesh.faces) {
    for (const std::uint32_t index : face) {
      lo = lo.cwiseMin(mesh.vertices[index]);
      hi = hi.cwiseMax(mesh.vertices[index]);
    }
  }
  const double min_area = kDegenerateAreaScale * (hi - lo).squaredNorm();
  std::size_t kept = 0;
  std::size_t dropped = 0;
  std::string first;
  std::vector<std::size_t> group_faces(mesh.group_names.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (const auto reason = degenerate_reason(mesh, f, min_area, first_vertex_number)) {
      if (dropped++ == 0) first = where(f) + ": " + *reason;
      continue;
    }
    mesh.faces[kept] = mesh.faces[f];
    mesh.face_group[kept] = mesh.face_group[f];
    ++group_faces[mesh.face_group[kept]];
    ++kept;
  }
  if (kept == 0) {
    throw InputError(path, 0,
                     "no faces with an area: all " + std::to_string(dropped) +
                         " are degenerate (first, " + first + ")");
  }
  if (dropped == 0) return;
  report.degenerate_faces += dropped;
  if (report.first_degenerate.empty()) report.first_degenerate = first;
  mesh.faces.resize(kept);
  mesh.face_group.resize(kept);
  std::vector<std::uint32_t> renumbered(group_faces.size(), 0);
  std::vector<std::string> names;
  for (std::size_t g = 0; g < group_faces.size(); ++g) {
    if (group_faces[g] == 0) continue;
    renumbered[g] = static_cast<std::uint32_t>(names.size());
    names.push_back(std::move(mesh.group_names[g]));
  }
  mesh.group_names = std::move(names);
  for (std::uint32_t& group : mesh.face_group) group = renumbered[group];
}

}  // namespace occlusion::detail
