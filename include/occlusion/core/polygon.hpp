#pragma once
// Planar polygons: openings (windows, doors) marked by points picked on their
// boundary (thesis 3.3.3). The points are fitted with a least-squares plane,
// projected onto it, and kept in order as a 2-D polygon in the plane's own
// coordinates. Inside tests use the crossing-number (even-odd) rule, right for
// any simple polygon, convex or not; points on the boundary count as inside.
//
// Rules:
// - Boundary: a point closer to an edge than 1e-9 x the polygon's diameter is
//   on it, and inside. That absorbs the rounding of projecting onto the plane.
// - Rays: a hit counts iff t_min <= t <= t_max (closed), as for triangles. A
//   ray in the plane (|d . n| <= 1e-7 |d|, the triangles' tolerance) misses.
//   Both faces are hit.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "occlusion/core/ray.hpp"

namespace occlusion {

class PlanarPolygon {
 public:
  // Throws std::invalid_argument for fewer than 3 points, non-finite points, or
  // points that span no plane (all collinear or coincident: the second-largest
  // spread is below 1e-6 of the largest).
  explicit PlanarPolygon(const std::vector<Eigen::Vector3d>& boundary);

  const Eigen::Vector3d& origin() const { return origin_; }  // centroid of the points
  // Unit, and oriented so that the boundary runs counter-clockwise seen from
  // the side it points to (vertices_2d() has positive signed area).
  const Eigen::Vector3d& normal() const { return normal_; }
  // The plane's in-plane axes: (axis_u, axis_v, normal) is right-handed and orthonormal.
  const Eigen::Vector3d& axis_u() const { return axis_u_; }
  const Eigen::Vector3d& axis_v() const { return axis_v_; }
  // The boundary projected onto the plane, in 3-D and in plane coordinates.
  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  const std::vector<Eigen::Vector2d>& vertices_2d() const { return vertices_2d_; }
  double area() const;  // of the projected polygon

  // Plane coordinates of a 3-D point (projected along the normal).
  Eigen::Vector2d to_plane(const Eigen::Vector3d& point) const;
  bool contains(const Eigen::Vector2d& point) const;
  // Where the ray crosses the polygon, t in [t_min, t_max]; nothing for a ray
  // parallel to the plane.
  std::optional<double> intersect(const Ray& ray) const;

 private:
  bool on_boundary(const Eigen::Vector2d& point) const;

  Eigen::Vector3d origin_, normal_, axis_u_, axis_v_;
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Eigen::Vector2d> vertices_2d_;
  double boundary_tolerance_ = 0.0;
};

}  // namespace occlusion
