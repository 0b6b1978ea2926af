#include "occlusion/analysis/cloud_occlusion.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "support/cloud_scenes.hpp"

namespace occlusion {
namespace {

// A viewpoint at the centre of a closed sphere shell of points (radius 1), with
// a circular hole around +z. A ray from the centre hits the point at c iff it
// passes within r of c, i.e. iff its angle to c is at most a = asin(r / R). So
// with every point whose polar angle is below alpha + a removed, and a dense
// ring of points left exactly at alpha + a, the rays that escape are exactly
// those with polar angle below alpha (up to scallops between ring points of
// depth spacing^2 / (8 a), about a / 800 here): the occlusion level is the
// cap's share of the sphere, (1 - cos alpha) / 2.
constexpr double kRadius = 0.02;
constexpr double kAlpha = M_PI / 4;
const Eigen::Vector3d kCentre = Eigen::Vector3d::Zero();

double rim_angle() {
  return std::asin(kRadius);
}
double cap_share(double alpha) {
  return (1.0 - std::cos(alpha)) / 2.0;
}
double polar_angle(const Eigen::Vector3d& d) {
  return std::acos(std::clamp(d.z() / d.norm(), -1.0, 1.0));
}

// 60000 shell points are 0.0145 apart, their covering radius well below r.
const PointCloud& shell(bool with_hole) {
  static const PointCloud closed = [] {
    PointCloud cloud;
    testing::add_sphere_shell(cloud, kCentre, 1.0, 60000);
    return cloud;
  }();
  static const PointCloud holed = [] {
    PointCloud cloud;
    const double edge = kAlpha + rim_angle();
    testing::add_sphere_shell(cloud, kCentre, 1.0, 60000,
                              [edge](const Eigen::Vector3d& d) { return polar_angle(d) < edge; });
    testing::add_circle(cloud, kCentre, 1.0, edge, kRadius / 10);
    return cloud;
  }();
  return with_hole ? holed : closed;
}

CloudOcclusionOptions shell_options(DirectionSampling sampling, std::size_t rays,
                                    std::uint64_t seed = 1) {
  CloudOcclusionOptions options;
  options.point_radius = kRadius;
  options.num_rays_per_vp = rays;
  options.sampling = sampling;
  options.seed = seed;
  return options;
}

// How many of the viewpoint's directions satisfy `pred`: the exact count the
// geometry allows, for the same rays the analysis traces.
template <class Pred>
std::size_t count_directions(const CloudOcclusionOptions& options, std::size_t viewpoint,
                             Pred pred) {
  const SphereDirections directions(options.sampling, options.num_rays_per_vp, options.seed,
                                    viewpoint);
  std::size_t count = 0;
  for (std::size_t i = 0; i < directions.size(); ++i) count += pred(directions(i)) ? 1 : 0;
  return count;
}

double binomial_sigma(double p, std::size_t n) {
  return std::sqrt(p * (1 - p) / static_cast<double>(n));
}

TEST(CloudOcclusion, ClosedShellStopsEveryRay) {
  for (const auto sampling : {DirectionSampling::kUniform, DirectionSampling::kFibonacci}) {
    const auto result =
        compute_cloud_occlusion(shell(false), {kCentre}, {}, shell_options(sampling, 20000));
    EXPECT_EQ(result.occlusion_rays, 0u);
    EXPECT_EQ(result.hits, 20000u);
    EXPECT_EQ(result.occlusion_level, 0.0);
    EXPECT_EQ(result.points, shell(false).size());
    EXPECT_EQ(result.blocking_points, shell(false).size());
  }
}

TEST(CloudOcclusion, UniformLevelIsTheHoleShareWithinBinomialNoise) {
  const std::size_t rays = 20000;
  const double expected = cap_share(kAlpha);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const auto result = compute_cloud_occlusion(
        shell(true), {kCentre}, {}, shell_options(DirectionSampling::kUniform, rays, seed));
    EXPECT_NEAR(result.occlusion_level, expected, 4 * binomial_sigma(expected, rays));
    EXPECT_EQ(result.hits + result.occlusion_rays, rays);
    EXPECT_EQ(result.through_openings, 0u);
  }
}

TEST(CloudOcclusion, FibonacciLevelIsTheHoleShareWithFarLessError) {
  // A lattice has no binomial noise: a cap's count is off by a few lattice
  // points along its rim (at most 5 of 20000 over ten seeds), a twentieth of
  // the uniform tolerance.
  const std::size_t rays = 20000;
  const double expected = cap_share(kAlpha);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const auto result = compute_cloud_occlusion(
        shell(true), {kCentre}, {}, shell_options(DirectionSampling::kFibonacci, rays, seed));
    EXPECT_NEAR(result.occlusion_level, expected, 0.2 * binomial_sigma(expected, rays));
  }
}

TEST(CloudOcclusion, EscapingRaysAreExactlyThoseInsideTheHoleCone) {
  for (const auto sampling : {DirectionSampling::kUniform, DirectionSampling::kFibonacci}) {
    auto options = shell_options(sampling, 20000);
    options.keep_escape_directions = true;
    const auto result = compute_cloud_occlusion(shell(true), {kCentre}, {}, options);
    const double scallop = rim_angle() / 100;
    const std::size_t sure = count_directions(
        options, 0, [](const Eigen::Vector3d& d) { return polar_angle(d) < kAlpha; });
    const std::size_t possible = count_directions(
        options, 0, [&](const Eigen::Vector3d& d) { return polar_angle(d) < kAlpha + scallop; });
    EXPECT_GE(result.occlusion_rays, sure);
    EXPECT_LE(result.occlusion_rays, possible);
    ASSERT_EQ(result.viewpoints.size(), 1u);
    const auto& escapes = result.viewpoints[0].escape_directions;
    ASSERT_EQ(escapes.size(), result.occlusion_rays);
    for (const Eigen::Vector3f& d : escapes) {
      EXPECT_NEAR(d.norm(), 1.0f, 1e-6f);
      EXPECT_LT(polar_angle(d.cast<double>()), kAlpha + scallop);
    }
  }
}

TEST(CloudOcclusion, OpeningBeyondTheHoleTurnsEveryEscapeIntoAnExit) {
  // A square at z = 1.5, past the shell, wider than the hole's cone there
  // (1.5 tan 45 deg = 1.5): rays that hit the shell reach the shell first.
  const PlanarPolygon window({{-2, -2, 1.5}, {2, -2, 1.5}, {2, 2, 1.5}, {-2, 2, 1.5}});
  const auto options = shell_options(DirectionSampling::kUniform, 20000);
  const auto open = compute_cloud_occlusion(shell(true), {kCentre}, {}, options);
  const auto covered = compute_cloud_occlusion(shell(true), {kCentre}, {window}, options);
  EXPECT_EQ(covered.occlusion_rays, 0u);
  EXPECT_EQ(covered.occlusion_level, 0.0);
  EXPECT_EQ(covered.through_openings, open.occlusion_rays);
  EXPECT_EQ(covered.hits, open.hits);
  EXPECT_GT(covered.through_openings, 0u);
  EXPECT_EQ(covered.viewpoints[0].through_openings, covered.through_openings);
}

TEST(CloudOcclusion, OpeningCrossedBeforeThePointHitCountsAsAnExit) {
  // A square at z = 0.5 of half-width 1 inside the shell: a ray with polar
  // angle beta crosses it at distance 0.5 / cos(beta), before the shell (which
  // it enters between 1 - r and 1) iff beta is below about 60 degrees.
  const PlanarPolygon screen({{-1, -1, 0.5}, {1, -1, 0.5}, {1, 1, 0.5}, {-1, 1, 0.5}});
  const auto options = shell_options(DirectionSampling::kFibonacci, 20000);
  const auto result = compute_cloud_occlusion(shell(true), {kCentre}, {screen}, options);
  EXPECT_EQ(result.occlusion_rays, 0u);
  const std::size_t sure = count_directions(
      options, 0, [](const Eigen::Vector3d& d) { return d.z() > 0.5 / (1 - kRadius); });
  const std::size_t possible =
      count_directions(options, 0, [](const Eigen::Vector3d& d) { return d.z() >= 0.5; });
  EXPECT_GE(result.through_openings, sure);
  EXPECT_LE(result.through_openings, possible);
  EXPECT_NEAR(static_cast<double>(result.through_openings) / 20000, cap_share(M_PI / 3), 0.01);
}

TEST(CloudOcclusion, RaysStartOnTheLightSphere) {
  auto options = shell_options(DirectionSampling::kFibonacci, 5000);
  // Starting outside the shell and going outwards, nothing can be hit.
  options.light_radius = 1.5;
  EXPECT_EQ(compute_cloud_occlusion(shell(true), {kCentre}, {}, options).occlusion_level, 1.0);
  // Inside it the rays are the same lines from the centre, so the same escape.
  options.light_radius = 0.5;
  const auto inner = compute_cloud_occlusion(shell(true), {kCentre}, {}, options);
  const double scallop = rim_angle() / 100;
  EXPECT_GE(inner.occlusion_rays, count_directions(options, 0, [](const Eigen::Vector3d& d) {
              return polar_angle(d) < kAlpha;
            }));
  EXPECT_LE(inner.occlusion_rays, count_directions(options, 0, [&](const Eigen::Vector3d& d) {
              return polar_angle(d) < kAlpha + scallop;
            }));
}

TEST(CloudOcclusion, NonBlockingPointsStopNothing) {
  auto options = shell_options(DirectionSampling::kUniform, 2000);
  options.blocking.assign(shell(false).size(), false);
  const auto result = compute_cloud_occlusion(shell(false), {kCentre}, {}, options);
  EXPECT_EQ(result.blocking_points, 0u);
  EXPECT_EQ(result.points, shell(false).size());
  EXPECT_EQ(result.occlusion_level, 1.0);
}

TEST(CloudOcclusion, SameSeedSameRaysWhateverTheThreadCount) {
  for (const auto sampling : {DirectionSampling::kUniform, DirectionSampling::kFibonacci}) {
    auto options = shell_options(sampling, 40000, 11);  // more than one block
    options.keep_escape_directions = true;
    options.threads = 1;
    const auto one = compute_cloud_occlusion(shell(true), {kCentre, {0, 0, 0.2}}, {}, options);
    options.threads = 2;
    const auto two = compute_cloud_occlusion(shell(true), {kCentre, {0, 0, 0.2}}, {}, options);
    ASSERT_EQ(one.viewpoints.size(), 2u);
    for (std::size_t v = 0; v < 2; ++v) {
      EXPECT_EQ(one.viewpoints[v].occlusion_rays, two.viewpoints[v].occlusion_rays);
      EXPECT_EQ(one.viewpoints[v].escape_directions, two.viewpoints[v].escape_directions);
    }
    options.seed = 12;
    const auto other = compute_cloud_occlusion(shell(true), {kCentre, {0, 0, 0.2}}, {}, options);
    EXPECT_NE(one.viewpoints[0].escape_directions, other.viewpoints[0].escape_directions);
  }
}

TEST(CloudOcclusion, ViewpointsAreCountedSeparately) {
  // Off centre towards the hole, the hole looks larger: more escapes.
  const auto options = shell_options(DirectionSampling::kFibonacci, 10000);
  const auto both = compute_cloud_occlusion(shell(true), {kCentre, {0, 0, 0.5}}, {}, options);
  const auto first = compute_cloud_occlusion(shell(true), {kCentre}, {}, options);
  ASSERT_EQ(both.viewpoints.size(), 2u);
  // Viewpoint 0 gets the same rays alone or with company.
  EXPECT_EQ(both.viewpoints[0].occlusion_rays, first.occlusion_rays);
  EXPECT_GT(both.viewpoints[1].occlusion_level, both.viewpoints[0].occlusion_level);
  EXPECT_EQ(both.rays, 20000u);
  EXPECT_EQ(both.viewpoints[1].rays, 10000u);
  EXPECT_EQ(both.occlusion_rays,
            both.viewpoints[0].occlusion_rays + both.viewpoints[1].occlusion_rays);
  EXPECT_DOUBLE_EQ(both.occlusion_level,
                   (both.viewpoints[0].occlusion_level + both.viewpoints[1].occlusion_level) / 2);
  EXPECT_EQ(both.viewpoints[1].position, Eigen::Vector3d(0, 0, 0.5));
}

TEST(CloudOcclusion, BruteForceModeGivesTheSameAnswer) {
  PointCloud sparse;
  testing::add_sphere_shell(sparse, kCentre, 1.0, 3000);
  auto options = shell_options(DirectionSampling::kUniform, 3000);
  options.point_radius = 0.03;
  options.keep_escape_directions = true;
  const auto fast = compute_cloud_occlusion(sparse, {{0.1, 0, 0}}, {}, options);
  options.octree.enable_acceleration = false;
  const auto slow = compute_cloud_occlusion(sparse, {{0.1, 0, 0}}, {}, options);
  EXPECT_GT(fast.occlusion_rays, 0u);  // gaps between sparse points
  EXPECT_EQ(fast.viewpoints[0].escape_directions, slow.viewpoints[0].escape_directions);
  EXPECT_EQ(slow.octree.leaves, 1u);
}

TEST(CloudOcclusion, RejectsBadInput) {
  const PointCloud& cloud = shell(false);
  const CloudOcclusionOptions good = shell_options(DirectionSampling::kUniform, 100);
  EXPECT_THROW(compute_cloud_occlusion(PointCloud{}, {kCentre}, {}, good), std::invalid_argument);
  EXPECT_THROW(compute_cloud_occlusion(cloud, {}, {}, good), std::invalid_argument);
  EXPECT_THROW(compute_cloud_occlusion(cloud, {{0, NAN, 0}}, {}, good), std::invalid_argument);
  auto options = good;
  options.point_radius = 0;
  EXPECT_THROW(compute_cloud_occlusion(cloud, {kCentre}, {}, options), std::invalid_argument);
  options = good;
  options.point_radius = INFINITY;
  EXPECT_THROW(compute_cloud_occlusion(cloud, {kCentre}, {}, options), std::invalid_argument);
  options = good;
  options.num_rays_per_vp = 0;
  EXPECT_THROW(compute_cloud_occlusion(cloud, {kCentre}, {}, options), std::invalid_argument);
  options = good;
  options.blocking.assign(cloud.size() - 1, true);
  EXPECT_THROW(compute_cloud_occlusion(cloud, {kCentre}, {}, options), std::invalid_argument);
  options = good;
  options.light_radius = -1;
  EXPECT_THROW(compute_cloud_occlusion(cloud, {kCentre}, {}, options), std::invalid_argument);
  PointCloud bad = cloud;
  bad.positions[5].x() = NAN;
  EXPECT_THROW(compute_cloud_occlusion(bad, {kCentre}, {}, good), std::invalid_argument);
}

TEST(CloudOcclusion, CancelStopsWithCancelled) {
  std::atomic<bool> cancel{true};
  Progress progress;
  progress.cancel = &cancel;
  EXPECT_THROW(compute_cloud_occlusion(shell(false), {kCentre}, {},
                                       shell_options(DirectionSampling::kUniform, 100), progress),
               Cancelled);
}

TEST(CloudOcclusion, ReportsTracingProgressUpToOne) {
  std::vector<double> tracing;
  double last = -1;
  Progress progress;
  progress.report = [&](const std::string& stage, double fraction) {
    if (stage == "tracing") tracing.push_back(fraction);
    last = fraction;
  };
  compute_cloud_occlusion(shell(false), {kCentre, kCentre}, {},
                          shell_options(DirectionSampling::kUniform, 40000), progress);
  ASSERT_GE(tracing.size(), 3u);  // several blocks
  EXPECT_TRUE(std::is_sorted(tracing.begin(), tracing.end()));
  EXPECT_DOUBLE_EQ(tracing.back(), 1.0);
  EXPECT_DOUBLE_EQ(last, 1.0);
}

TEST(CloudOcclusion, InteriorExteriorRatioCountsPoints) {
  EXPECT_DOUBLE_EQ(interior_exterior_ratio({true, false, false, true, false}), 1.5);
  EXPECT_DOUBLE_EQ(interior_exterior_ratio({true, true}), 0.0);
  EXPECT_EQ(interior_exterior_ratio({false, false}), INFINITY);
}

}  // namespace
}  // namespace occlusion
