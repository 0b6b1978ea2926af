// The surface noise model against noise of a known sigma: a floor scanned
// from a station above it, with Gaussian range noise drawn here.

#include "occlusion/analysis/surface_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

double gaussian(Rng& rng) {
  const double u = std::max(rng.uniform(), 1e-300), v = rng.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
}

// A 4 x 4 m floor at z = 0 on a 1 cm grid, each point moved along its line of
// sight from (2, 2, 1.5) by N(0, sigma) (a laser's range noise).
PointCloud noisy_floor(double sigma, std::uint64_t seed) {
  PointCloud cloud;
  Station station{"s", {}};
  station.frame.origin = Eigen::Vector3d(2.0, 2.0, 1.5);
  cloud.stations = {station};
  Rng rng(seed);
  for (int i = 0; i < 400; ++i) {
    for (int j = 0; j < 400; ++j) {
      const Eigen::Vector3d p(0.01 * i, 0.01 * j, 0.0);
      const Eigen::Vector3d sight = (p - station.frame.origin).normalized();
      cloud.positions.push_back((p + sigma * gaussian(rng) * sight).cast<float>());
    }
  }
  return cloud;
}

SurfaceNoise noise_of(const PointCloud& cloud) {
  return estimate_surfels(cloud, SurfelOptions{}).noise;
}

TEST(SurfaceNoise, ReadsTheSigmaOfItsStationsRangeNoise) {
  for (const double sigma : {0.001, 0.003}) {
    SCOPED_TRACE(sigma);
    const SurfaceNoise noise = noise_of(noisy_floor(sigma, 3));
    ASSERT_EQ(noise.stations.size(), 1u);
    EXPECT_EQ(noise.stations[0].station, "s");
    // Ranges 1.5 m (below the station) to 3.2 m (the corners): four bins of
    // 1.25 each, every one within the noise it measures (the lower quartile
    // reads about 0.8 sigma; kBandSigmas allows for it).
    EXPECT_GE(noise.stations[0].bins.size(), 3u);
    for (const NoiseBin& bin : noise.stations[0].bins) {
      EXPECT_NEAR(bin.range_hi / bin.range_lo, kNoiseBinRatio, 1e-9);
      EXPECT_GE(bin.sigma, 0.5 * sigma) << bin.range_lo;
      EXPECT_LE(bin.sigma, 1.3 * sigma) << bin.range_lo;
    }
    ASSERT_EQ(noise.sigma.size(), 160000u);
  }
}

TEST(SurfaceNoise, AFloorWithoutNoiseHasNone) {
  const SurfaceNoise noise = noise_of(noisy_floor(0.0, 3));
  for (const NoiseBin& bin : noise.stations.at(0).bins) EXPECT_LT(bin.sigma, 1e-5);
}

TEST(SurfaceNoise, ACloudNoStationClaimsIsOneBin) {
  PointCloud cloud = noisy_floor(0.002, 5);
  cloud.stations.clear();
  const SurfaceNoise noise = noise_of(cloud);
  ASSERT_EQ(noise.stations.size(), 1u);
  EXPECT_EQ(noise.stations[0].station, "");
  ASSERT_EQ(noise.stations[0].bins.size(), 1u);
  EXPECT_NEAR(noise.stations[0].bins[0].sigma, 0.002, 0.001);
}

// A wall 3 m in front of a camera (+z forward), 200 x 150 pixels, turned
// about the vertical so that its depth grows 0.5 m per unit of x / z; its
// depths get N(0, sigma) noise, then are rounded to multiples of `step` (0:
// not rounded), as a depth camera's disparity does.
PointCloud camera_wall(double sigma, double step) {
  PointCloud cloud;
  cloud.sensor.width = 200;
  cloud.sensor.height = 150;
  const double f = 150.0;
  Rng rng(8);
  for (std::uint32_t r = 0; r < 150; ++r) {
    for (std::uint32_t c = 0; c < 200; ++c) {
      const double x = (c - 99.5) / f, y = (r - 74.5) / f;
      const double depth = 3.0 + 0.5 * x + sigma * gaussian(rng);
      const double stepped = step > 0.0 ? step * std::round(depth / step) : depth;
      cloud.positions.emplace_back(static_cast<float>(x * stepped), static_cast<float>(y * stepped),
                                   static_cast<float>(stepped));
      cloud.pixels.push_back(r * 200 + c);
    }
  }
  return cloud;
}

// The bins of the camera's one station with enough points.
std::vector<NoiseBin> filled_bins(const PointCloud& cloud) {
  const SurfelEstimate estimate = estimate_surfels(cloud, SurfelOptions{});
  EXPECT_EQ(estimate.noise.stations.size(), 1u);
  EXPECT_EQ(estimate.noise.stations.at(0).station, "sensor");
  std::vector<NoiseBin> bins;
  for (const NoiseBin& bin : estimate.noise.stations.at(0).bins) {
    if (bin.points >= kMinBinPoints) bins.push_back(bin);
  }
  EXPECT_GE(bins.size(), 1u);
  return bins;
}

TEST(SurfaceNoise, AnOrganisedFramesStepsCountAsItsNoise) {
  // Noise of 5 mm and steps of 2 cm: the error of a depth is both together,
  // sigma sqrt(5^2 + 20^2 / 12) = 7.7 mm (read: 12 to 14 mm, the steps'
  // jumps weigh more than a Gaussian's tail).
  for (const NoiseBin& bin : filled_bins(camera_wall(0.005, 0.02))) {
    EXPECT_GT(bin.sigma, 0.005) << bin.range_lo;
    EXPECT_LT(bin.sigma, 0.02) << bin.range_lo;
  }
}

TEST(SurfaceNoise, AFramesFlatTreadsCountAsTheirRounding) {
  // Steps of 2 cm and no noise, as a real camera's matching window gives
  // (pixels side by side share a step): the planes fit the treads exactly
  // and the rows' second differences are mostly zero, but the rounding's
  // error, uniform over a step, is 20 mm / sqrt(12) = 5.8 mm.
  for (const NoiseBin& bin : filled_bins(camera_wall(0.0, 0.02))) {
    EXPECT_GT(bin.sigma, 0.8 * 0.02 / std::sqrt(12.0)) << bin.range_lo;
    EXPECT_LT(bin.sigma, 1.5 * 0.02 / std::sqrt(12.0)) << bin.range_lo;
  }
  // Not rounded, the same wall's depths change a little from every pixel to
  // the next and none of it is noise.
  for (const NoiseBin& bin : filled_bins(camera_wall(0.0, 0.0))) {
    EXPECT_LT(bin.sigma, 1e-4) << bin.range_lo;
  }
}

// The frame as a bare array: no grid, the camera's pose kept (a PCD whose
// VIEWPOINT says where it was seen from), as a frame is after its missing
// depths were dropped.
PointCloud bare(PointCloud frame) {
  frame.pixels.clear();
  frame.sensor.width = frame.sensor.height = 0;
  frame.sensor.origin = Eigen::Vector3d(0.0, 0.0, 0.0);
  frame.sensor.orientation = Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0);  // PCL's grabbers write it
  return frame;
}

TEST(SurfaceNoise, ABareFramesTreadsAreReadFromItsNeighbours) {
  for (const NoiseBin& bin : filled_bins(bare(camera_wall(0.0, 0.02)))) {
    EXPECT_GT(bin.sigma, 0.8 * 0.02 / std::sqrt(12.0)) << bin.range_lo;
    EXPECT_LT(bin.sigma, 1.5 * 0.02 / std::sqrt(12.0)) << bin.range_lo;
  }
  for (const NoiseBin& bin : filled_bins(bare(camera_wall(0.0, 0.0)))) {
    EXPECT_LT(bin.sigma, 1e-4) << bin.range_lo;
  }
}

}  // namespace
}  // namespace occlusion
