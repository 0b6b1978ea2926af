// The disc model against what it promises: the radius rule on a hand-worked
// case, planes found where the points lie on one, and discs that close a
// sampled surface to the share asked for, whether it is sampled at random, with
// density falling 4x across it, or on a 5:1 scanner grid.

#include "occlusion/analysis/surfel_estimation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/core/surfel_octree.hpp"

namespace occlusion {
namespace {

TEST(SurfelEstimation, CoverageRadiusFollowsTheBooleanModel) {
  // m = 16 distinct neighbours out to D = 2, coverage 0.999:
  // r = 2 sqrt(ln(1000) / 15) = 2 sqrt(0.460517) = 2 x 0.678614 = 1.357228.
  EXPECT_NEAR(coverage_radius(2.0, 16, 0.999), 1.357228, 1e-6);
  // Coverage 1 - e^-1 asks for rho pi r^2 = 1: with m - 1 = 4, r = D / 2.
  EXPECT_NEAR(coverage_radius(3.0, 5, 1.0 - std::exp(-1.0)), 1.5, 1e-12);
}

// Points at random on the square [0, side]^2 of the plane z = 0, with density
// rho(x) proportional to 1 + (falloff - 1) x / side.
PointCloud random_plane(std::size_t count, double side, double falloff, std::uint64_t seed) {
  Rng rng(seed);
  PointCloud cloud;
  while (cloud.size() < count) {
    const double x = side * rng.uniform(), y = side * rng.uniform();
    // Rejection: keep with probability rho(x) / rho_max.
    const double keep = (1.0 + (falloff - 1.0) * x / side) / falloff;
    if (rng.uniform() > keep) continue;
    cloud.positions.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
  }
  return cloud;
}

// The share of vertical rays through random spots of [lo, hi]^2 that meet no disc.
double open_share(const SurfelEstimate& estimate, double lo, double hi, std::uint64_t seed) {
  const SurfelOctree tree(estimate.surfels, surfel_octree_options());
  Rng rng(seed);
  std::size_t open = 0;
  const std::size_t rays = 20000;
  for (std::size_t i = 0; i < rays; ++i) {
    const auto x = static_cast<float>(lo + (hi - lo) * rng.uniform());
    const auto y = static_cast<float>(lo + (hi - lo) * rng.uniform());
    // Slanted 60 degrees from the normal: coverage does not depend on the angle.
    const Ray ray{{x - 1.0f, y, 1.0f}, {1.0f, 0.0f, -0.57735f}, 0.0f, 10.0f};
    open += tree.occluded(ray) ? 0 : 1;
  }
  return static_cast<double>(open) / static_cast<double>(rays);
}

TEST(SurfelEstimation, RandomSamplesOfAPlaneAreClosedToTheShareAskedFor) {
  const PointCloud cloud = random_plane(40000, 10.0, 1.0, 1);
  for (const double coverage : {0.99, 0.999}) {
    SurfelOptions options;
    options.coverage = coverage;
    const SurfelEstimate estimate = estimate_surfels(cloud, options);
    EXPECT_EQ(estimate.stats.oriented, cloud.size());
    for (const Surfel& s : estimate.surfels) {
      ASSERT_NEAR(std::abs(s.normal.z()), 1.0f, 1e-5f);
    }
    // Away from the edges (where neighbours lie on one side only).
    const double open = open_share(estimate, 1.0, 9.0, 2);
    EXPECT_LE(open, 2.0 * (1.0 - coverage)) << coverage;
    // Not so large that they are closed far beyond the rule: the rule's share
    // is reached, give or take the estimate's spread.
    if (coverage == 0.99) {
      EXPECT_GE(open, 0.1 * (1.0 - coverage));
    }
  }
}

TEST(SurfelEstimation, DensityFallingFourfoldIsClosedEverywhere) {
  const PointCloud cloud = random_plane(40000, 10.0, 4.0, 3);
  SurfelOptions options;
  options.coverage = 0.999;
  const SurfelEstimate estimate = estimate_surfels(cloud, options);
  EXPECT_LE(open_share(estimate, 1.0, 3.0, 4), 0.003);  // the sparse side
  EXPECT_LE(open_share(estimate, 7.0, 9.0, 5), 0.003);  // the dense side
  // The radii follow the density: mean densities 1.15 (x < 1) and 3.85
  // (x > 9), so radii sqrt(3.85 / 1.15) = 1.83 times larger on the sparse side.
  double dense = 0, sparse = 0;
  std::size_t n_dense = 0, n_sparse = 0;
  for (const Surfel& s : estimate.surfels) {
    if (s.center.x() < 1.0f) sparse += s.radius, ++n_sparse;
    if (s.center.x() > 9.0f) dense += s.radius, ++n_dense;
  }
  EXPECT_NEAR((sparse / n_sparse) / (dense / n_dense), 1.83, 0.2);
}

TEST(SurfelEstimation, AnisotropicScannerGridIsClosed) {
  // Rows 1 cm apart, columns 5 cm apart, a little jitter as a scanner has.
  PointCloud cloud;
  Rng rng(6);
  for (int i = 0; i <= 200; ++i) {
    for (int j = 0; j <= 1000; ++j) {
      cloud.positions.emplace_back(static_cast<float>(0.05 * i + 0.002 * (rng.uniform() - 0.5)),
                                   static_cast<float>(0.01 * j + 0.002 * (rng.uniform() - 0.5)),
                                   0.0f);
    }
  }
  const SurfelEstimate estimate = estimate_surfels(cloud, SurfelOptions{});
  EXPECT_GT(estimate.stats.oriented, cloud.size() * 99 / 100);
  EXPECT_EQ(open_share(estimate, 1.0, 9.0, 7), 0.0);
}

TEST(SurfelEstimation, PointsStoredTwiceCountOnce) {
  const PointCloud once = random_plane(20000, 10.0, 1.0, 8);
  PointCloud twice = once;
  twice.positions.insert(twice.positions.end(), once.positions.begin(), once.positions.end());
  const SurfelEstimate a = estimate_surfels(once, SurfelOptions{});
  const SurfelEstimate b = estimate_surfels(twice, SurfelOptions{});
  EXPECT_EQ(a.stats.duplicates, 0u);
  EXPECT_EQ(b.stats.duplicates, twice.size());
  // Twice the points, the same gaps: the radii stay those of the single cloud
  // (fewer distinct neighbours are in reach, so the estimate is noisier).
  EXPECT_NEAR(b.stats.radius_median / a.stats.radius_median, 1.0, 0.15);
}

void expect_same_spacing(const PointSpacing& a, const PointSpacing& b) {
  EXPECT_EQ(a.spacing, b.spacing);
  EXPECT_EQ(a.quantile_10, b.quantile_10);
  EXPECT_EQ(a.quantile_90, b.quantile_90);
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_EQ(a.duplicate_hits, b.duplicate_hits);
}

TEST(SurfelEstimation, ItsSearchMeasuresThePointSpacingBitForBit) {
  // 50,000 points (a stride sample of 25,000) stored once and twice, and
  // 22,500 (every point a sample), 2,500 of them stored eight times: those
  // have a kd-tree's eight nearest at their own position, and no distance.
  PointCloud once = random_plane(50000, 10.0, 4.0, 12);
  PointCloud twice = once;
  twice.positions.insert(twice.positions.end(), once.positions.begin(), once.positions.end());
  PointCloud eightfold;
  for (int copy = 0; copy < 8; ++copy) {
    eightfold.positions.insert(eightfold.positions.end(), once.positions.begin(),
                               once.positions.begin() + 2500);
  }
  eightfold.positions.insert(eightfold.positions.end(), once.positions.begin() + 2500,
                             once.positions.begin() + 5000);
  for (const PointCloud* cloud : {&once, &twice, &eightfold}) {
    const SurfelEstimate estimate = estimate_surfels(*cloud, SurfelOptions{});
    ASSERT_TRUE(estimate.spacing);
    expect_same_spacing(*estimate.spacing, measure_point_spacing(*cloud));
  }
  EXPECT_GT(measure_point_spacing(twice).duplicate_hits, 19000u);
  // Six neighbours do not reach a kd-tree's eight: the spacing is measured apart.
  SurfelOptions few;
  few.neighbours = 6;
  EXPECT_FALSE(estimate_surfels(once, few).spacing);
}

TEST(SurfelEstimation, StrayPointsBecomeSmallSpheres) {
  PointCloud cloud = random_plane(20000, 10.0, 1.0, 9);
  cloud.positions.emplace_back(5.0f, 5.0f, 3.0f);  // in the air, 3 m above the floor
  const SurfelEstimate estimate = estimate_surfels(cloud, SurfelOptions{});
  const Surfel& stray = estimate.surfels.back();
  EXPECT_FALSE(stray.oriented());
  EXPECT_LT(stray.radius, 2.0 * estimate.stats.radius_median);
  EXPECT_EQ(estimate.stats.stray, 1u);
}

TEST(SurfelEstimation, EdgesAndLinesAreSpheres) {
  PointCloud cloud;
  // One line of points: no plane.
  for (int i = 0; i < 100; ++i) cloud.positions.emplace_back(0.01f * i, 0.0f, 0.0f);
  const SurfelEstimate line = estimate_surfels(cloud, SurfelOptions{});
  EXPECT_EQ(line.stats.oriented, 0u);
  // The corner of a box: points on three faces near it are not on one plane.
  PointCloud corner;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      corner.positions.emplace_back(0.01f * i, 0.01f * j, 0.0f);
      corner.positions.emplace_back(0.0f, 0.01f * i + 0.005f, 0.01f * j + 0.005f);
      corner.positions.emplace_back(0.01f * i + 0.005f, 0.0f, 0.01f * j + 0.005f);
    }
  }
  const SurfelEstimate estimate = estimate_surfels(corner, SurfelOptions{});
  // The point nearest the corner has neighbours on all three faces.
  EXPECT_FALSE(estimate.surfels[0].oriented());
}

TEST(SurfelEstimation, SameInputSameModelOnAnyThreadCount) {
  const PointCloud cloud = random_plane(30000, 10.0, 2.0, 10);
  SurfelOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const SurfelEstimate a = estimate_surfels(cloud, one);
  const SurfelEstimate b = estimate_surfels(cloud, two);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    ASSERT_EQ(a.surfels[i].radius, b.surfels[i].radius);
    ASSERT_EQ(a.surfels[i].normal, b.surfels[i].normal);
  }
}

TEST(SurfelEstimation, RefusesWhatItCannotModel) {
  PointCloud one_point;
  one_point.positions.emplace_back(0.0f, 0.0f, 0.0f);
  EXPECT_THROW(estimate_surfels(one_point, SurfelOptions{}), std::invalid_argument);
  PointCloud same;
  for (int i = 0; i < 40; ++i) same.positions.emplace_back(1.0f, 1.0f, 1.0f);
  EXPECT_THROW(estimate_surfels(same, SurfelOptions{}), std::invalid_argument);
  const PointCloud plane = random_plane(100, 1.0, 1.0, 11);
  SurfelOptions bad;
  bad.coverage = 1.0;
  EXPECT_THROW(estimate_surfels(plane, bad), std::invalid_argument);
  bad = SurfelOptions{};
  bad.neighbours = 2;
  EXPECT_THROW(estimate_surfels(plane, bad), std::invalid_argument);
  PointCloud far = plane;
  far.positions.emplace_back(3e38f, 0.0f, 0.0f);
  EXPECT_THROW(estimate_surfels(far, SurfelOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
