// A laser station's points in the order its beams swept (analysis/beam_order):
// a scan made here, beam by beam, of a wall 3 m away, a floor 1.2 m below and
// a plate 1.5 m away standing in front of the wall (depth edges), with
// Gaussian range noise drawn here.

#include "occlusion/analysis/beam_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

constexpr double kStepDegrees = 0.5;

double gaussian(Rng& rng) {
  const double u = std::max(rng.uniform(), 1e-300), v = rng.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
}

// The nearest of the wall, the floor and the plate along `beam` (unit).
double true_range(const Eigen::Vector3d& beam) {
  double range = std::numeric_limits<double>::infinity();
  if (beam.x() > 0.0) {
    range = 3.0 / beam.x();
    const Eigen::Vector3d plate = 1.5 / beam.x() * beam;
    if (std::abs(plate.y()) < 0.2 && plate.z() > -1.2 && plate.z() < 0.3) range = 1.5 / beam.x();
  }
  if (beam.z() < 0.0) range = std::min(range, 1.2 / -beam.z());
  return range;
}

// From the origin, rows at one elevation (-40 to 20 degrees, each sweeping
// azimuth -45 to 45 degrees), or with `profiles` the same beams as vertical
// profiles (each azimuth sweeping elevation: great circles, as a survey
// scanner's mirror turns); each range moved by N(0, sigma), then rounded to
// a multiple of `rounding` (0: not rounded).
PointCloud scan(double sigma, std::uint64_t seed, double rounding = 0.0, bool profiles = false) {
  PointCloud cloud;
  cloud.stations = {{"station", {}}};
  Rng rng(seed);
  const int elevations = 121, azimuths = 181;
  for (int outer = 0; outer < (profiles ? azimuths : elevations); ++outer) {
    for (int inner = 0; inner < (profiles ? elevations : azimuths); ++inner) {
      const int row = profiles ? inner : outer, column = profiles ? outer : inner;
      const double e = (-40.0 + kStepDegrees * row) * M_PI / 180.0;
      const double a = (-45.0 + kStepDegrees * column) * M_PI / 180.0;
      const Eigen::Vector3d beam(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
      double range = true_range(beam) + sigma * gaussian(rng);
      if (rounding > 0.0) range = rounding * std::round(range / rounding);
      cloud.positions.push_back((range * beam).cast<float>());
    }
  }
  return cloud;
}

BeamOrder order_of(const PointCloud& cloud) {
  return find_beam_order(cloud, scan_stations(cloud));
}

TEST(BeamOrder, AScanInItsBeamsOrderIsFoundWithItsStep) {
  const PointCloud cloud = scan(0.005, 1);
  const BeamOrder order = order_of(cloud);
  ASSERT_EQ(order.step.size(), 1u);
  EXPECT_TRUE(order.in_beam_order(0));
  EXPECT_EQ(order.model[0], BeamOrder::Model::kAzimuth);
  EXPECT_NEAR(order.step[0] * 180.0 / M_PI, kStepDegrees, 1e-4);
  // All but each row's two ends (181 beams a row).
  EXPECT_GT(order.regular_share[0], 0.98);
  // As vertical profiles: equal angles between consecutive beams.
  const BeamOrder profiles = order_of(scan(0.005, 1, 0.0, true));
  EXPECT_TRUE(profiles.in_beam_order(0));
  EXPECT_EQ(profiles.model[0], BeamOrder::Model::kAngle);
  EXPECT_NEAR(profiles.step[0] * 180.0 / M_PI, kStepDegrees, 1e-4);
}

TEST(BeamOrder, FromBesideTheStationItIsNot) {
  // A step changes by about the offset over the range: at this scan's 1.5
  // to 4 m, 5 cm is within what counts as equal (0.91 of the points between
  // equal steps), 20 cm is not.
  for (const Eigen::Vector3d& offset :
       {Eigen::Vector3d(0.2, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 0.2),
        Eigen::Vector3d(1.0, 0.5, 0.0)}) {
    SCOPED_TRACE(offset.transpose());
    PointCloud cloud = scan(0.005, 1);
    cloud.stations[0].frame.origin = offset;
    const BeamOrder order = order_of(cloud);
    EXPECT_FALSE(order.in_beam_order(0)) << order.regular_share[0];
  }
}

TEST(BeamOrder, ShuffledPointsAreNot) {
  PointCloud cloud = scan(0.005, 1);
  Rng rng(7);
  for (std::size_t i = cloud.size() - 1; i > 0; --i) {
    std::swap(
        cloud.positions[i],
        cloud.positions[static_cast<std::size_t>(rng.uniform() * static_cast<double>(i + 1))]);
  }
  EXPECT_FALSE(order_of(cloud).in_beam_order(0));
}

TEST(BeamOrder, EveryPointStoredTwiceInARowStillIs) {
  const PointCloud once = scan(0.005, 1);
  PointCloud twice = once;
  twice.positions.clear();
  for (const Eigen::Vector3f& p : once.positions) {
    twice.positions.push_back(p);
    twice.positions.push_back(p);
  }
  const BeamOrder order = order_of(twice);
  EXPECT_TRUE(order.in_beam_order(0));
  EXPECT_DOUBLE_EQ(order.step[0], order_of(once).step[0]);
}

TEST(BeamOrder, TheChordOffsetIsTheNoiseWhateverTheIncidence) {
  // Without noise every offset of three returns on one flat surface is
  // about zero, the floor seen at 5 degrees of elevation as well as the wall
  // head on. (A row at one elevation is a cone, not a plane: its middle beam
  // bends off its neighbours' plane by about step^2 / 2, 4e-5 of the range,
  // and more along the beam at grazing incidence: below 1e-4 of it here, a
  // tenth of a millimetre a metre.)
  const PointCloud exact = scan(0.0, 1);
  const std::vector<Station> stations = scan_stations(exact);
  const BeamOrder order = find_beam_order(exact, stations);
  // Which surface a return lies on: the wall, the floor or the plate.
  const auto surface = [&](std::size_t i) {
    const Eigen::Vector3f& p = exact.positions[i];
    if (std::abs(p.z() + 1.2f) < 1e-4f) return 0;
    return std::abs(p.x() - 3.0f) < 1e-4f ? 1 : 2;
  };
  std::size_t flat = 0;
  for_each_beam_triple(exact, stations, order, [&](const BeamTriple& triple) {
    EXPECT_NEAR(triple.range, exact.positions[triple.point].cast<double>().norm(), 1e-9);
    const std::size_t i = triple.point;
    if (surface(i - 1) != surface(i) || surface(i + 1) != surface(i)) return;  // a corner or edge
    ++flat;
    EXPECT_LT(std::abs(triple.offset), 1e-4 * triple.range) << exact.positions[i].transpose();
  });
  EXPECT_GT(flat, exact.size() * 9 / 10);

  // With noise sigma along each beam, the offsets' standard deviation is
  // about sqrt(3/2) sigma (the middle return's own and half its two
  // neighbours'; at grazing incidence a little more).
  const double sigma = 0.004;
  const PointCloud noisy = scan(sigma, 2);
  std::vector<double> offsets;
  for_each_beam_triple(noisy, stations, find_beam_order(noisy, stations),
                       [&](const BeamTriple& triple) {
                         const std::size_t i = triple.point;
                         if (surface(i - 1) == surface(i) && surface(i + 1) == surface(i)) {
                           offsets.push_back(triple.offset);
                         }
                       });
  double squares = 0.0;
  for (const double offset : offsets) squares += offset * offset;
  EXPECT_NEAR(std::sqrt(squares / static_cast<double>(offsets.size())), std::sqrt(1.5) * sigma,
              0.1 * std::sqrt(1.5) * sigma);
}

TEST(BeamOrder, TheNoiseOfAStationInBeamOrderIsReadFromItsReturns) {
  // The plane fits' quartile reads about 0.8 sigma; consecutive returns of
  // vertical profiles read sigma itself. (Rows at one elevation are not
  // read: surface_noise.cpp says why.)
  const double sigma = 0.004;
  const SurfelEstimate estimate = estimate_surfels(scan(sigma, 3, 0.0, true), SurfelOptions{});
  ASSERT_EQ(estimate.noise.stations.size(), 1u);
  const StationNoise& station = estimate.noise.stations[0];
  EXPECT_TRUE(station.beam_order);
  EXPECT_NEAR(station.beam_step * 180.0 / M_PI, kStepDegrees, 1e-4);
  std::size_t filled = 0;
  for (const NoiseBin& bin : station.bins) {
    if (bin.points < kMinBinPoints) continue;
    ++filled;
    EXPECT_NEAR(bin.sigma, sigma, 0.15 * sigma) << bin.range_lo;
  }
  EXPECT_GE(filled, 3u);
}

TEST(BeamOrder, RangesRoundedToACentimetreHeadOnReadAsTheirRoundingError) {
  // The wall head on (ranges 3.0 to 3.1 m): most returns share their rounded
  // range with the next, so a plane's residuals and the chords read about 0
  // there; the rounding's error is uniform over a step, sigma = 1 cm /
  // sqrt(12). (Where a slanted surface's range grows by about one step a
  // beam, rounded ranges come in exact progressions and the chords still
  // read about 0: not handled, docs/architecture.md.)
  const double rounding = 0.01, sigma = rounding / std::sqrt(12.0);
  const SurfelEstimate estimate = estimate_surfels(scan(0.0, 1, rounding, true), SurfelOptions{});
  ASSERT_EQ(estimate.noise.stations.size(), 1u);
  std::size_t head_on = 0;
  for (const NoiseBin& bin : estimate.noise.stations[0].bins) {
    if (bin.range_hi <= 3.0 || bin.range_lo >= 3.1 || bin.points < kMinBinPoints) continue;
    ++head_on;
    EXPECT_GE(bin.sigma, 0.7 * sigma) << bin.range_lo;
    EXPECT_LE(bin.sigma, 1.5 * sigma) << bin.range_lo;
  }
  EXPECT_GE(head_on, 1u);
}

}  // namespace
}  // namespace occlusion
