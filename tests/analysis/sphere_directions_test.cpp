#include "occlusion/analysis/sphere_directions.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace occlusion {
namespace {

// The share of `directions` in the cap of half-angle 60 degrees around `axis`;
// the cap holds a quarter of the sphere.
double cap_fraction(const SphereDirections& directions, const Eigen::Vector3d& axis) {
  std::size_t inside = 0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    inside += directions(i).dot(axis) > 0.5 ? 1 : 0;
  }
  return static_cast<double>(inside) / static_cast<double>(directions.size());
}

TEST(SphereDirections, FibonacciLatticeIsUnitAndEqualArea) {
  const std::size_t n = 10000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = fibonacci_direction(i, n);
    EXPECT_NEAR(d.norm(), 1.0, 1e-12);
    sum += d;
  }
  EXPECT_LT(sum.norm() / n, 1e-4);
  // Each point owns a band of equal height in z, so equal area.
  EXPECT_NEAR(fibonacci_direction(0, n).z(), 1 - 1.0 / n, 1e-15);
  EXPECT_NEAR(fibonacci_direction(n - 1, n).z(), -1 + 1.0 / n, 1e-15);
}

TEST(SphereDirections, UniformRotationIsARotation) {
  for (const double u : {0.0, 0.3, 0.99}) {
    const Eigen::Matrix3d r = uniform_rotation(u, 1 - u, 0.5 * u);
    EXPECT_TRUE((r * r.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  }
}

TEST(SphereDirections, BothSamplingsCoverCapsInProportion) {
  const std::size_t n = 20000;
  const double sigma = std::sqrt(0.25 * 0.75 / n);
  for (const Eigen::Vector3d& axis : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, -1, 0.5)}) {
    const SphereDirections uniform(DirectionSampling::kUniform, n, 4, 0);
    const SphereDirections lattice(DirectionSampling::kFibonacci, n, 4, 0);
    EXPECT_NEAR(cap_fraction(uniform, axis.normalized()), 0.25, 4 * sigma);
    EXPECT_NEAR(cap_fraction(lattice, axis.normalized()), 0.25, 0.2 * sigma);
  }
}

TEST(SphereDirections, DependOnSeedAndViewpointOnly) {
  for (const auto sampling : {DirectionSampling::kUniform, DirectionSampling::kFibonacci}) {
    const SphereDirections a(sampling, 100, 9, 2), same(sampling, 100, 9, 2);
    const SphereDirections other_seed(sampling, 100, 10, 2), other_view(sampling, 100, 9, 3);
    for (std::size_t i = 0; i < 100; ++i) {
      EXPECT_EQ(a(i), same(i));
      EXPECT_NEAR(a(i).norm(), 1.0, 1e-12);
    }
    EXPECT_NE(a(7), other_seed(7));
    EXPECT_NE(a(7), other_view(7));
  }
  // The lattice is rotated as a whole: angles between its points are kept.
  const SphereDirections r1(DirectionSampling::kFibonacci, 100, 1, 0);
  const SphereDirections r2(DirectionSampling::kFibonacci, 100, 2, 0);
  EXPECT_NEAR(r1(3).dot(r1(40)), r2(3).dot(r2(40)), 1e-12);
  EXPECT_NEAR(r1(3).dot(r1(40)), fibonacci_direction(3, 100).dot(fibonacci_direction(40, 100)),
              1e-12);
  EXPECT_THROW(SphereDirections(DirectionSampling::kUniform, 0, 1, 0), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
