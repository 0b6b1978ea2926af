#include "occlusion/core/sphere.hpp"

#include <stdexcept>
#include <string>

namespace occlusion {

Aabb Sphere::bounds() const {
  Aabb box;
  box.lo = center.array() - radius;
  box.hi = center.array() + radius;
  return box;
}

LargeVector<Sphere> make_spheres(const std::vector<Eigen::Vector3f>& centers, float radius) {
  if (!(radius > 0.0f) || !std::isfinite(radius)) {
    throw std::invalid_argument("spheres: point radius must be finite and > 0, got " +
                                std::to_string(radius));
  }
  LargeVector<Sphere> spheres;
  spheres.reserve(centers.size());
  for (std::size_t i = 0; i < centers.size(); ++i) {
    if (!centers[i].allFinite()) {
      throw std::invalid_argument("spheres: point " + std::to_string(i) + " is not finite");
    }
    spheres.push_back(Sphere{centers[i], radius});
  }
  return spheres;
}

}  // namespace occlusion
