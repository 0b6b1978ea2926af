#include "support/scenes.hpp"

#include <algorithm>

namespace occlusion::testing {

namespace {
std::uint32_t group_index(TriangleMesh& mesh, const std::string& group) {
  const auto it = std::find(mesh.group_names.begin(), mesh.group_names.end(), group);
  if (it != mesh.group_names.end()) {
    return static_cast<std::uint32_t>(it - mesh.group_names.begin());
  }
  mesh.group_names.push_back(group);
  return static_cast<std::uint32_t>(mesh.group_names.size() - 1);
}
}  // namespace

void add_quad(TriangleMesh& mesh, const Eigen::Vector3d& corner, const Eigen::Vector3d& edge_a,
              const Eigen::Vector3d& edge_b, const std::string& group) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(corner);
  mesh.vertices.push_back(corner + edge_a);
  mesh.vertices.push_back(corner + edge_a + edge_b);
  mesh.vertices.push_back(corner + edge_b);
  const std::uint32_t g = group_index(mesh, group);
  mesh.faces.push_back({base, base + 1, base + 2});
  mesh.faces.push_back({base, base + 2, base + 3});
  mesh.face_group.push_back(g);
  mesh.face_group.push_back(g);
}

void add_box(TriangleMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
             const std::string& group, int n) {
  const Eigen::Vector3d size = hi - lo;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    Eigen::Vector3d step_a = Eigen::Vector3d::Zero(), step_b = Eigen::Vector3d::Zero();
    step_a[a] = size[a] / n;
    step_b[b] = size[b] / n;
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          Eigen::Vector3d corner = lo + i * step_a + j * step_b;
          corner[axis] = side == 0 ? lo[axis] : hi[axis];
          add_quad(mesh, corner, step_a, step_b, group);
        }
      }
    }
  }
}

}  // namespace occlusion::testing
