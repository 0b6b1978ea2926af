#pragma once
// Tessellates the few shapes the synthetic room is made of into an
// occlusion::TriangleMesh, in metres, z up.
//
// `density` is the number of grid cells per metre along every edge, profile
// and arc, so doubling it roughly quadruples the triangle count; every shape
// keeps a floor (one cell per panel, eight slices per circle) so that a low
// density still gives recognisable furniture. No shape emits a zero-area
// triangle: the OBJ reader rejects them.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/core/mesh.hpp"

namespace occlusion::bench {

// A point of a lathe profile: distance from the axis and height.
struct ProfilePoint {
  double r = 0.0;
  double z = 0.0;
};

class MeshBuilder {
 public:
  explicit MeshBuilder(double density);

  // Faces added from now on belong to the group `name` (an OBJ `g`).
  void begin_group(const std::string& name);

  // The parallelogram origin + a u + b v for a, b in [0, 1]; u x v is its front.
  void add_panel(const Eigen::Vector3d& origin, const Eigen::Vector3d& u, const Eigen::Vector3d& v);
  // A closed axis-aligned box, front faces outwards.
  void add_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  // A surface of revolution about the vertical line through `axis` (x, y).
  // A profile point with r == 0 closes the surface there (a cap or an apex);
  // an end with r > 0 stays open. Consecutive points must differ.
  void add_lathe(const Eigen::Vector2d& axis, const std::vector<ProfilePoint>& profile);
  void add_sphere(const Eigen::Vector3d& centre, double radius);

  std::size_t triangle_count() const { return mesh_.faces.size(); }
  TriangleMesh take() { return std::move(mesh_); }

 private:
  std::size_t divisions(double length, std::size_t minimum) const;
  std::uint32_t add_vertex(const Eigen::Vector3d& p);
  void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void revolve(const Eigen::Vector2d& axis, const std::vector<ProfilePoint>& profile,
               std::size_t slices);

  double density_;
  TriangleMesh mesh_;
};

}  // namespace occlusion::bench
