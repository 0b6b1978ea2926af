#pragma once
// Ray directions of the spherical light source (thesis 3.3.1), one per ray
// index, so that any block of rays can be generated on its own and the result
// depends only on (seed, viewpoint index, ray index), never on blocking or threads.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>

namespace occlusion {

enum class DirectionSampling {
  kUniform,    // the seed's theta/phi sampling, seeded
  kFibonacci,  // a Fibonacci lattice, randomly rotated per viewpoint: lower variance
};

class SphereDirections {
 public:
  // `count` directions for the viewpoint with index `viewpoint`. Throws
  // std::invalid_argument for count == 0.
  SphereDirections(DirectionSampling sampling, std::size_t count, std::uint64_t seed,
                   std::size_t viewpoint);

  std::size_t size() const { return count_; }
  // Unit direction of ray `index` < size().
  Eigen::Vector3d operator()(std::size_t index) const;

 private:
  DirectionSampling sampling_;
  std::size_t count_;
  std::uint64_t seed_;
  std::size_t viewpoint_;
  Eigen::Matrix3d rotation_;  // Fibonacci only
};

// Point `index` of the golden-angle spiral of `count` points: equal-area bands
// in z, one point each, turned by the golden angle from the previous one.
Eigen::Vector3d fibonacci_direction(std::size_t index, std::size_t count);

// A rotation uniform over SO(3) (Shoemake's unit quaternion) from three numbers
// uniform in [0, 1).
Eigen::Matrix3d uniform_rotation(double u1, double u2, double u3);

}  // namespace occlusion
