#include "occlusion/core/sampling.hpp"

#include <cmath>

namespace occlusion {

Eigen::Vector3d sample_triangle(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                const Eigen::Vector3d& v2, double r1, double r2) {
  const double sqrt_r1 = std::sqrt(r1);
  const double alpha = 1.0 - sqrt_r1;
  const double beta = r2 * sqrt_r1;
  return alpha * v0 + beta * v1 + (1.0 - alpha - beta) * v2;
}

Eigen::Vector3d sample_sphere_direction(double r1, double r2) {
  const double theta = 2.0 * M_PI * r1;
  const double phi = std::acos(2.0 * r2 - 1.0);
  return {std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi)};
}

}  // namespace occlusion
