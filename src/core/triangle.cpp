#include "occlusion/core/triangle.hpp"

#include <cmath>

namespace occlusion {

namespace {
// Relative tolerance of the parallel test |d . n| <= kParallelTolerance |d| |n|:
// about the float rounding of the determinant itself.
constexpr float kParallelTolerance = 1e-7f;
}  // namespace

Aabb Triangle::bounds() const {
  Aabb box;
  box.extend(v0);
  box.extend(v1);
  box.extend(v2);
  return box;
}

double Triangle::area() const {
  const Eigen::Vector3d a = v0.cast<double>();
  return 0.5 * (v1.cast<double>() - a).cross(v2.cast<double>() - a).norm();
}

PackedTriangle::PackedTriangle(const Triangle& tri)
    : v0(tri.v0), e1(tri.v1 - tri.v0), e2(tri.v2 - tri.v0) {
  normal = e1.cross(e2);
  normal_length = normal.norm();
}

Aabb PackedTriangle::bounds() const {
  Aabb box;
  box.extend(v0);
  box.extend(v0 + e1);
  box.extend(v0 + e2);
  return box;
}

std::optional<float> intersect_triangle(const Ray& ray, float direction_length,
                                        const PackedTriangle& tri) {
  // Möller–Trumbore with det = e1 . (d x e2) = -(d . n), using the stored normal.
  const float det = -ray.direction.dot(tri.normal);
  if (!(std::abs(det) > kParallelTolerance * direction_length * tri.normal_length)) {
    return std::nullopt;  // parallel to the plane, or a degenerate triangle (n = 0)
  }
  const float inv_det = 1.0f / det;
  const Eigen::Vector3f s = ray.origin - tri.v0;
  const Eigen::Vector3f p = ray.direction.cross(tri.e2);
  const float u = s.dot(p) * inv_det;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const Eigen::Vector3f q = s.cross(tri.e1);
  const float v = ray.direction.dot(q) * inv_det;
  if (v < 0.0f || u + v > 1.0f) return std::nullopt;
  const float t = tri.e2.dot(q) * inv_det;
  if (t < ray.t_min || t > ray.t_max) return std::nullopt;
  return t;
}

}  // namespace occlusion
