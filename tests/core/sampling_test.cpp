#include "occlusion/core/sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

TEST(Rng, SameSeedAndStreamSameSequence) {
  Rng a(5, 3), b(5, 3), c(5, 4), d(6, 3);
  bool c_differs = false, d_differs = false;
  for (int i = 0; i < 100; ++i) {
    const auto x = a.next();
    EXPECT_EQ(x, b.next());
    c_differs = c_differs || x != c.next();
    d_differs = d_differs || x != d.next();
  }
  EXPECT_TRUE(c_differs);
  EXPECT_TRUE(d_differs);
}

TEST(Rng, UniformIsInUnitIntervalWithMeanOneHalf) {
  Rng rng(1);
  double sum = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  // Standard error of the mean is 1/sqrt(12 n) ~ 0.0009.
  EXPECT_NEAR(sum / n, 0.5, 0.005);
}

TEST(Sampling, TriangleSamplesAreInsideAndUniform) {
  const Eigen::Vector3d v0(0, 0, 0), v1(2, 0, 0), v2(0, 1, 0);
  Rng rng(3);
  const int n = 100000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int left_half = 0;  // x < 1 holds 3/4 of this triangle's area
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = sample_triangle(v0, v1, v2, rng.uniform(), rng.uniform());
    ASSERT_GE(p.x(), -1e-12);
    ASSERT_GE(p.y(), -1e-12);
    ASSERT_LE(p.x() / 2 + p.y(), 1.0 + 1e-12);
    sum += p;
    left_half += p.x() < 1.0 ? 1 : 0;
  }
  const Eigen::Vector3d centroid = (v0 + v1 + v2) / 3.0;
  EXPECT_NEAR((sum / n - centroid).norm(), 0.0, 0.01);
  EXPECT_NEAR(static_cast<double>(left_half) / n, 0.75, 0.006);
}

TEST(Sampling, SphereDirectionsAreUnitAndUniform) {
  Rng rng(4);
  const int n = 100000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int upper_cap = 0;  // z > 0.5: a cap holding 1/4 of the sphere
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d d = sample_sphere_direction(rng.uniform(), rng.uniform());
    ASSERT_NEAR(d.norm(), 1.0, 1e-12);
    sum += d;
    upper_cap += d.z() > 0.5 ? 1 : 0;
  }
  EXPECT_LT((sum / n).norm(), 0.01);
  EXPECT_NEAR(static_cast<double>(upper_cap) / n, 0.25, 0.006);
}

}  // namespace
}  // namespace occlusion
