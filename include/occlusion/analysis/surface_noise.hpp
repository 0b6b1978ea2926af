#pragma once
// The noise of a cloud's surfaces as its sensors measured them, per station
// and range, so that -fscan can tell a surface's own scatter from what lies
// in front of it (core/banded_surfel.hpp).
//
// A sensor's noise grows with range (a laser's sigma = a + b r; a depth
// camera's with the square of depth, in disparity steps), and one surface
// scatters by the same amount wherever it is; an edge, a corner or a thin
// board's far side inflates a single point's measure but not the median of
// the thousands at that range. So the noise is read per station in range
// bins (each 1.25 times the last, from the station's nearest point), as the
// median of the thickness of the points with a fitted plane (surfel_estimation.hpp: the lower
// quartile of their neighbours' distances from their plane). In an organised
// frame that thickness misses noise that comes in steps (a depth camera's
// quantised depths put most of a point's window on its own step): the bin
// takes the larger of it and the noise read off the grid, the median
// |d(c-1) - 2 d(c) + d(c+1)| of depths along the rows, over its expectation
// for Gaussian noise, 0.6745 sqrt(6) sigma, or, where most neighbouring
// pixels' depths are exactly equal (a real depth camera's rounded depths,
// whose treads are flat), the rounding's error: the median step between
// neighbours over sqrt(12). A laser station stored in its beams' order
// (beam_order.hpp) reads its range noise the same way from consecutive
// returns, their offsets from their neighbours' chords, which a fitted
// plane's residuals underrate (a real scanner's noise has long tails, and a
// point's nearest neighbours in space are those its noise moved least). A
// bin of fewer than
// kMinBinPoints points takes its nearest filled bin's; a cloud whose points
// no station claims is one bin.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/analysis/beam_order.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/surfel.hpp"

namespace occlusion {

struct NoiseBin {
  double range_lo = 0.0, range_hi = 0.0;  // scene units from the station
  std::size_t points = 0;                 // oriented points measured in it
  double sigma = 0.0;                     // scene units
};

struct StationNoise {
  std::string station;  // its name, or "" for points no station claims
  std::vector<NoiseBin> bins;
  bool beam_order = false;  // its points are stored as its beams swept (beam_order.hpp)
  double beam_step = 0.0;   // then the angle between consecutive beams, radians
};

struct SurfaceNoise {
  std::vector<StationNoise> stations;
  // Per point, the sigma of its bin (0 for unoriented points).
  std::vector<float> sigma;
};

// A disc hides a point only where the point lies off the disc's plane by
// more than this many times the noise measured for the disc's surface
// (surface_noise.hpp; core/banded_surfel.hpp). Two points of one surface
// differ by sqrt(2) sigma, three sigmas either way is 4.2 sigma, and the
// measure (the neighbours' lower quartile) reads about 0.8 sigma; a disc's
// normal, fitted to noisy neighbours, tilts it further off at its rim. On
// simulated scans (sigma 1 to 5 mm, a Kinect's noise and steps) 4 kept
// 99.18 % of a room from its station, 8 kept 99.25 % and agreed better with
// the mesh from elsewhere (docs/simulate.md has the figures).
inline constexpr float kBandSigmas = 8.0f;

inline constexpr std::size_t kMinBinPoints = 100;
inline constexpr double kNoiseBinRatio = 1.25;

// `surfels`, `thickness` and `measured` are one per point
// (surfel_estimation.hpp); measured[i] != 0 where point i's thickness was
// measured from a plane fitted to its neighbours (a disc that faces its
// station for want of a plane was not). `beams` is find_beam_order's for
// the cloud's scan_stations.
SurfaceNoise measure_surface_noise(const PointCloud& cloud, const LargeVector<Surfel>& surfels,
                                   const std::vector<float>& thickness,
                                   const std::vector<std::uint8_t>& measured,
                                   const BeamOrder& beams);

}  // namespace occlusion
