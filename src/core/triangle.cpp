#include "occlusion/core/triangle.hpp"

namespace occlusion {

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

}  // namespace occlusion
