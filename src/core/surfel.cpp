#include "occlusion/core/surfel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace occlusion {

namespace {

// The disc's box is widened by this share of its radius: the kernel rounds its
// crossing, and a box that cut the rim by an ulp would hide a hit from the
// octree that brute force finds.
constexpr float kBoxMargin = 1e-4f;

}  // namespace

Aabb Surfel::bounds() const {
  Aabb box;
  if (!oriented()) {
    box.lo = center.array() - radius;
    box.hi = center.array() + radius;
    return box;
  }
  // A disc of unit normal n reaches r sqrt(1 - n_i^2) from its centre along axis i.
  const Eigen::Array3f reach =
      radius * ((1.0f - normal.array().square()).max(0.0f).sqrt() + kBoxMargin);
  box.lo = center.array() - reach;
  box.hi = center.array() + reach;
  return box;
}

Surfel make_surfel(const Eigen::Vector3f& center, const Eigen::Vector3f& normal, float radius,
                   std::size_t index) {
  if (!center.allFinite() || !normal.allFinite()) {
    throw std::invalid_argument("surfels: point " + std::to_string(index) + " is not finite");
  }
  if (!(radius > 0.0f) || !std::isfinite(radius)) {
    throw std::invalid_argument(
        "surfels: point " + std::to_string(index) +
        " has a radius that is not finite and > 0: " + std::to_string(radius));
  }
  const float length = normal.norm();
  return Surfel{center, radius,
                length > 0.0f ? Eigen::Vector3f(normal / length) : Eigen::Vector3f::Zero()};
}

LargeVector<Surfel> make_surfels(const std::vector<Eigen::Vector3f>& centers,
                                 const std::vector<Eigen::Vector3f>& normals,
                                 const std::vector<float>& radii) {
  if (normals.size() != centers.size() || radii.size() != centers.size()) {
    throw std::invalid_argument("surfels: " + std::to_string(centers.size()) + " centres, " +
                                std::to_string(normals.size()) + " normals and " +
                                std::to_string(radii.size()) + " radii");
  }
  LargeVector<Surfel> surfels;
  surfels.reserve(centers.size());
  for (std::size_t i = 0; i < centers.size(); ++i) {
    surfels.push_back(make_surfel(centers[i], normals[i], radii[i], i));
  }
  return surfels;
}

}  // namespace occlusion
