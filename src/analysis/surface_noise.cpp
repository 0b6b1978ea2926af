#include "occlusion/analysis/surface_noise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "occlusion/core/morton_knn.hpp"
#include "occlusion/core/morton_order.hpp"
#include "occlusion/core/parallel.hpp"
#include "quantiles.hpp"

namespace occlusion {

namespace {

// E|N(0, 1) (x - 2 y + z)| at its median: 0.6745 sqrt(6).
constexpr double kSecondDifferenceMedian = 0.6745 * 2.449489742783178;

struct Binning {
  std::vector<Eigen::Vector3d> origins;  // per station
  std::vector<double> nearest;           // per station: its nearest point's range
  std::vector<std::size_t> bin_count;    // per station
  std::vector<std::size_t> first_bin;    // per station: its bins' offset in one flat array
  std::vector<std::ptrdiff_t> station;   // per point, or -1 for the cloud's one bin
};

std::size_t bin_index(const Binning& binning, std::size_t point, const PointCloud& cloud) {
  const std::ptrdiff_t s = binning.station[point];
  if (s < 0) return binning.first_bin.back();
  const auto st = static_cast<std::size_t>(s);
  const double range = (cloud.positions[point].cast<double>() - binning.origins[st]).norm();
  const double steps = std::log(std::max(range, binning.nearest[st]) / binning.nearest[st]) /
                       std::log(kNoiseBinRatio);
  const auto bin =
      std::min(static_cast<std::size_t>(std::max(0.0, steps)), binning.bin_count[st] - 1);
  return binning.first_bin[st] + bin;
}

// Per station, its nearest and farthest points' ranges make its bins; the
// last entry of first_bin is the one bin of points no station claims.
Binning make_binning(const PointCloud& cloud, const std::vector<Station>& stations) {
  Binning binning;
  binning.station.resize(cloud.size());
  const std::size_t count = stations.size();
  binning.nearest.assign(count, std::numeric_limits<double>::infinity());
  std::vector<double> farthest(count, 0.0);
  for (const Station& station : stations) binning.origins.push_back(station.frame.origin);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::ptrdiff_t s = measuring_station(cloud, count, i);
    binning.station[i] = s;
    if (s < 0) continue;
    const double range =
        (cloud.positions[i].cast<double>() - binning.origins[static_cast<std::size_t>(s)]).norm();
    if (!(range > 0.0)) continue;
    binning.nearest[static_cast<std::size_t>(s)] =
        std::min(binning.nearest[static_cast<std::size_t>(s)], range);
    farthest[static_cast<std::size_t>(s)] = std::max(farthest[static_cast<std::size_t>(s)], range);
  }
  std::size_t offset = 0;
  for (std::size_t s = 0; s < count; ++s) {
    if (!std::isfinite(binning.nearest[s])) binning.nearest[s] = 1.0;  // no point of its own
    const double span = std::max(farthest[s], binning.nearest[s]) / binning.nearest[s];
    const auto bins =
        static_cast<std::size_t>(std::floor(std::log(span) / std::log(kNoiseBinRatio))) + 1;
    binning.bin_count.push_back(bins);
    binning.first_bin.push_back(offset);
    offset += bins;
  }
  binning.first_bin.push_back(offset);
  return binning;
}

struct GridMeasures {
  // Per bin: |d(c-1) - 2 d(c) + d(c+1)| of ranges along the rows.
  std::vector<std::vector<float>> second_differences;
  // Per bin: the larger of the depth changes (along the camera's axis) from
  // a point to its next pixels in its row and its column where that is not
  // zero, and how many points it is zero for (points inside a tread).
  std::vector<std::vector<float>> depth_steps;
  std::vector<std::size_t> treads, points;
};

// A depth camera rounds its depths to steps (a Kinect's disparity in 1/8
// pixel: 11 mm at 2 m, 27 mm at 3 m) and its matching window makes pixels
// side by side share a step: a real frame's surfaces are staircases whose
// treads are exactly flat, so neither a plane's residuals nor the second
// differences (mostly zero) see the rounding. A disc fitted to a tread stands
// up to a step in front of the next tread's points. Where a share
// kTreadShare of the points have the same depth as their next pixels in row
// and column (a surface whose depth changes along a row but not down a
// column, unrounded, has none), the frame is read as rounded: a step is the
// larger of those changes below kStepEdge of the depth (not a depth edge),
// and the rounding's error is uniform over one step, sigma = step / sqrt(12).
// A real Kinect's floor at 3 m has treads under two rows tall, so the share
// asked is well below a half.
constexpr double kTreadShare = 0.3;
constexpr float kStepEdge = 0.05f;
// Depths equal as the sensor wrote them differ by a float's rounding once a
// posed frame's points are turned back into the camera's frame.
constexpr float kSameDepth = 1e-5f;

// A point's depth along its frame's camera axis (the sensor's +z), the
// quantity a depth camera rounds.
class CameraDepth {
 public:
  explicit CameraDepth(const SensorFrame& sensor)
      : origin_(sensor.origin), to_sensor_(sensor.orientation.conjugate()) {}
  float operator()(const Eigen::Vector3f& position) const {
    return static_cast<float>(std::abs((to_sensor_ * (position.cast<double>() - origin_)).z()));
  }

 private:
  Eigen::Vector3d origin_;
  Eigen::Quaterniond to_sensor_;
};

void add_grid_measures(const PointCloud& cloud, const std::vector<std::uint8_t>& measured,
                       const std::vector<std::uint32_t>& bin_of, GridMeasures& grid) {
  if (!cloud.has_pixels()) return;
  const std::size_t width = cloud.sensor.width, height = cloud.sensor.height;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> range(width * height, nan), depth(width * height, nan);
  const CameraDepth camera_depth(cloud.sensor);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    range[cloud.pixels[i]] =
        static_cast<float>((cloud.positions[i].cast<double>() - cloud.sensor.origin).norm());
    depth[cloud.pixels[i]] = camera_depth(cloud.positions[i]);
  }
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!measured[i]) continue;
    const std::size_t pixel = cloud.pixels[i], column = pixel % width, row = pixel / width;
    const std::uint32_t bin = bin_of[i];
    if (column > 0 && column + 1 < width && !std::isnan(range[pixel - 1]) &&
        !std::isnan(range[pixel + 1])) {
      grid.second_differences[bin].push_back(
          std::abs(range[pixel - 1] - 2.0f * range[pixel] + range[pixel + 1]));
    }
    if (column + 1 >= width || row + 1 >= height) continue;
    const float right = depth[pixel + 1], below = depth[pixel + width];
    if (std::isnan(right) || std::isnan(below)) continue;
    const float change = std::max(std::abs(right - depth[pixel]), std::abs(below - depth[pixel]));
    ++grid.points[bin];
    if (change <= kSameDepth * depth[pixel]) {
      ++grid.treads[bin];
    } else if (change < kStepEdge * depth[pixel]) {
      grid.depth_steps[bin].push_back(change);
    }
  }
}

// A camera's frame without its grid (a Kinect frame stored as a bare array,
// its missing depths dropped) has the same treads; they are read from each
// point's kStepNeighbours nearest in space: a point at least half of whose
// neighbours share its depth lies inside a tread, and a point's step is its
// smallest depth change to a neighbour below kStepEdge of its depth (the
// nearest in space of a tread's edge are mostly on its own tread).
constexpr std::size_t kStepNeighbours = 8;

void add_neighbour_steps(const PointCloud& cloud, const std::vector<std::uint8_t>& measured,
                         const std::vector<std::uint32_t>& bin_of, GridMeasures& grid) {
  if (cloud.has_pixels() || !cloud.stations.empty() || !cloud.sensor.single_view()) return;
  const std::size_t count = cloud.size();
  const std::vector<std::uint32_t> order = morton_order(cloud.positions);
  std::vector<Eigen::Vector3f> sorted(count);
  std::vector<float> depth(count);
  const CameraDepth camera_depth(cloud.sensor);
  for (std::size_t s = 0; s < count; ++s) {
    sorted[s] = cloud.positions[order[s]];
    depth[s] = camera_depth(sorted[s]);
  }
  const MortonKnn knn(sorted);
  // Per sorted point: its step (0: none) and whether it lies inside a tread.
  std::vector<float> step(count, 0.0f);
  std::vector<std::uint8_t> tread(count, 0), considered(count, 0);
  const MortonKnn::Visit visit = [&](std::size_t, std::size_t s, const std::uint32_t* ids,
                                     std::size_t got) {
    if (!measured[order[s]] || got < 2) return;
    std::size_t same = 0;
    float smallest = std::numeric_limits<float>::infinity();
    for (std::size_t j = 0; j < got; ++j) {
      if (ids[j] == s) continue;
      const float change = std::abs(depth[ids[j]] - depth[s]);
      if (change <= kSameDepth * depth[s]) {
        ++same;
      } else if (change < kStepEdge * depth[s]) {
        smallest = std::min(smallest, change);
      }
    }
    considered[s] = 1;
    tread[s] = 2 * same >= got - 1;
    if (std::isfinite(smallest)) step[s] = smallest;
  };
  parallel_for(count, 4096, 0, [&](std::size_t first, std::size_t last) {
    knn.search(nullptr, first, last, kStepNeighbours + 1, visit);
  });
  for (std::size_t s = 0; s < count; ++s) {
    const std::uint32_t bin = bin_of[order[s]];
    grid.points[bin] += considered[s];
    grid.treads[bin] += tread[s];
    if (step[s] > 0.0f) grid.depth_steps[bin].push_back(step[s]);
  }
}

// A laser station in beam order whose rows are great circles (planes
// through the station): each return's offset from its neighbours' chord,
// doubled (its standard deviation is sqrt(3/2) sigma, a second difference's
// sqrt(6) sigma), joins the bin's second differences. A laser rounds its
// ranges too (PCL's room scans to 1 cm: at 10 cm below the scanner most
// consecutive returns share theirs, and both measures read 0): the range
// changes to the next return count as a frame's depth steps. Rows at one
// elevation are left out: they are cones, whose chords bend off a flat
// surface by about step^2 / 2 of the range (0.46 mm at 3 m for 1 degree
// steps), and which sweep a floor at one range all round, so a noise-free
// scan would read both as noise.
void add_beam_measures(const PointCloud& cloud, const std::vector<Station>& stations,
                       const BeamOrder& beams, const std::vector<std::uint8_t>& measured,
                       const std::vector<std::uint32_t>& bin_of, GridMeasures& grid) {
  if (cloud.has_pixels()) return;
  for_each_beam_triple(cloud, stations, beams, [&](const BeamTriple& triple) {
    if (!measured[triple.point]) return;
    const auto station =
        static_cast<std::size_t>(measuring_station(cloud, stations.size(), triple.point));
    if (beams.model[station] != BeamOrder::Model::kAngle) return;
    const std::uint32_t bin = bin_of[triple.point];
    const double change = std::abs(triple.next_range - triple.range);
    ++grid.points[bin];
    if (change <= kSameDepth * triple.range) {
      ++grid.treads[bin];
    } else if (change < kStepEdge * triple.range) {
      grid.depth_steps[bin].push_back(static_cast<float>(change));
    }
    if (std::abs(triple.offset) >= kStepEdge * triple.range) return;  // a depth edge
    grid.second_differences[bin].push_back(static_cast<float>(2.0 * std::abs(triple.offset)));
  });
}

// The bin's sigma read off the grid (negative: none), the larger of the
// second differences' and the rounding's.
double grid_sigma(GridMeasures& grid, std::size_t bin) {
  double sigma = -1.0;
  std::vector<float>& differences = grid.second_differences[bin];
  if (differences.size() >= kMinBinPoints) {
    sigma = quantiles::at(differences, 0.5) / kSecondDifferenceMedian;
  }
  std::vector<float>& steps = grid.depth_steps[bin];
  if (steps.size() >= kMinBinPoints && static_cast<double>(grid.treads[bin]) >=
                                           kTreadShare * static_cast<double>(grid.points[bin])) {
    sigma = std::max(sigma, quantiles::at(steps, 0.5) / std::sqrt(12.0));
  }
  return sigma;
}

}  // namespace

SurfaceNoise measure_surface_noise(const PointCloud& cloud, const LargeVector<Surfel>& surfels,
                                   const std::vector<float>& thickness,
                                   const std::vector<std::uint8_t>& measured,
                                   const BeamOrder& beams) {
  const std::vector<Station> stations = scan_stations(cloud);
  const Binning binning = make_binning(cloud, stations);
  const std::size_t bins = binning.first_bin.back() + 1;
  std::vector<std::vector<float>> thicknesses(bins);
  GridMeasures grid;
  grid.second_differences.resize(bins);
  grid.depth_steps.resize(bins);
  grid.treads.assign(bins, 0);
  grid.points.assign(bins, 0);
  std::vector<std::uint32_t> bin_of(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    bin_of[i] = static_cast<std::uint32_t>(bin_index(binning, i, cloud));
    if (measured[i]) thicknesses[bin_of[i]].push_back(thickness[i]);
  }
  add_grid_measures(cloud, measured, bin_of, grid);
  add_neighbour_steps(cloud, measured, bin_of, grid);
  add_beam_measures(cloud, stations, beams, measured, bin_of, grid);

  std::vector<std::size_t> points(bins);
  std::vector<double> sigma(bins, -1.0);
  for (std::size_t b = 0; b < bins; ++b) {
    points[b] = thicknesses[b].size();
    if (points[b] < kMinBinPoints) continue;
    sigma[b] =
        std::max(static_cast<double>(quantiles::at(thicknesses[b], 0.5)), grid_sigma(grid, b));
  }
  // The cloud's median thickness, for a station without a filled bin.
  std::vector<float> all;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (measured[i]) all.push_back(thickness[i]);
  }
  const double overall = quantiles::at(all, 0.5);

  SurfaceNoise noise;
  for (std::size_t s = 0; s <= stations.size(); ++s) {
    const std::size_t first = binning.first_bin[s];
    const std::size_t count = s < stations.size() ? binning.bin_count[s] : 1;
    // Empty bins take their nearest filled one's sigma (the nearer one first).
    std::vector<double> filled(count, overall);
    for (std::size_t b = 0; b < count; ++b) {
      for (std::size_t step = 0; step < count; ++step) {
        if (b >= step && sigma[first + b - step] >= 0.0) {
          filled[b] = sigma[first + b - step];
          break;
        }
        if (b + step < count && sigma[first + b + step] >= 0.0) {
          filled[b] = sigma[first + b + step];
          break;
        }
      }
    }
    for (std::size_t b = 0; b < count; ++b) sigma[first + b] = filled[b];
    StationNoise station;
    station.station = s < stations.size() ? stations[s].name : "";
    if (s < stations.size()) {
      station.beam_order = beams.in_beam_order(s);
      station.beam_step = beams.step[s];
    }
    for (std::size_t b = 0; b < count; ++b) {
      if (points[first + b] == 0) continue;
      NoiseBin bin;
      if (s < stations.size()) {
        bin.range_lo = binning.nearest[s] * std::pow(kNoiseBinRatio, static_cast<double>(b));
        bin.range_hi = bin.range_lo * kNoiseBinRatio;
      }
      bin.points = points[first + b];
      bin.sigma = sigma[first + b];
      station.bins.push_back(bin);
    }
    if (!station.bins.empty()) noise.stations.push_back(std::move(station));
  }
  noise.sigma.resize(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    noise.sigma[i] = surfels[i].oriented() ? static_cast<float>(sigma[bin_of[i]]) : 0.0f;
  }
  return noise;
}

}  // namespace occlusion
