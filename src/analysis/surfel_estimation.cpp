// One exact k-nearest search per point (core/morton_knn.hpp, over the points
// in Morton order) for its plane and density, and a second search only for
// the points that may be stray.

#include "occlusion/analysis/surfel_estimation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis_support.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/core/morton_knn.hpp"
#include "occlusion/core/morton_order.hpp"
#include "occlusion/core/parallel.hpp"
#include "pcl_frame.hpp"
#include "quantiles.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;
// Points a thread takes at a time: each range's first leaf searches the tree
// alone (morton_knn.hpp), so ranges of a few thousand keep that to a few
// queries in a thousand.
constexpr std::size_t kGrain = 4096;
// A second eigenvalue below this share of the largest: the neighbours lie on a line.
constexpr double kMinSpread = 1e-3;
// Below this surface variation a neighbourhood is one flat surface: no refit.
constexpr double kFlatVariation = 0.01;
constexpr float kSphereShare = 0.5f;
constexpr double kRmsShare = 0.5;
// How many times more neighbours a point whose neighbours lie on a line asks for.
constexpr std::size_t kWideSearch = 4;
// cos 85 degrees: a fitted plane closer than this to the line of sight of the
// station that measured the point is not the surface (face_its_station).
constexpr double kMinSightCosine = 0.0872;
// lambda1 / lambda2 below which a neighbourhood lies along one line.
constexpr float kLineSpread = 0.25f;

// About 20 progress steps per pass, but no block so small that the threads idle.
std::size_t block_size(std::size_t count) {
  return std::max<std::size_t>(count / 20, 16384);
}

template <class Vector>
void release(Vector& values) {
  Vector().swap(values);
}

void check_options(const PointCloud& cloud, const SurfelOptions& options) {
  if (options.neighbours < kMinNeighbours || options.neighbours > 256) {
    throw std::invalid_argument("surfels: neighbours must be in [" +
                                std::to_string(kMinNeighbours) + ", 256], got " +
                                std::to_string(options.neighbours));
  }
  if (!(options.coverage > 0.0 && options.coverage < 1.0)) {
    throw std::invalid_argument("surfels: coverage must lie in (0, 1)");
  }
  if (!(options.fixed_radius >= 0.0) || !std::isfinite(options.fixed_radius)) {
    throw std::invalid_argument("surfels: a fixed radius must be finite and >= 0");
  }
  if (!(options.max_surface_variation >= 0.0 && options.max_surface_variation <= 1.0 / 3.0)) {
    throw std::invalid_argument("surfels: max_surface_variation must lie in [0, 1/3]");
  }
  if (cloud.size() < 2) throw std::invalid_argument("surfels: the cloud needs at least two points");
  // The grid's points are looked up by pixel: each must be in it, once.
  if (cloud.has_pixels()) cloud.validate();
  for (const Eigen::Vector3f& p : cloud.positions) {
    if (!(p.cwiseAbs().maxCoeff() <= pcl_frame::kMaxLocalCoordinate)) {
      throw std::invalid_argument(
          "surfels: a point is not finite or lies more than 1e15 units from the cloud's "
          "origin, beyond what float distances between neighbours resolve; remove the stray far "
          "points (or fix the unit) first");
    }
  }
}

// What one point's neighbourhood says.
struct Neighbourhood {
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();  // zero: not trusted
  float radius = 0.0f;                               // 0: no distinct neighbour
  float thickness = 0.0f;
  float surface_variation = 0.0f;
  bool duplicate = false;
  bool line = false;    // the neighbours lie along one line: no plane among them
  float spread = 0.0f;  // lambda1 / lambda2: across the neighbourhood's longest spread
};

// The distinct positions among a point's nearest (nearest first, the point
// itself among them): a neighbour at the point's position, or at one already
// taken, is the same position stored again.
class Distinct {
 public:
  void reset(const Eigen::Vector3f& own, double same) {
    own_ = own;
    same_ = same;
    kept_.clear();
    distance_.clear();
    duplicate_ = false;
  }
  // The neighbours ids[0..got) of `points`, nearest first, but `self`. Their
  // distances are taken first, apart: each root then waits on nothing.
  void offer_all(const Eigen::Vector3f* points, const std::uint32_t* ids, std::size_t got,
                 std::size_t self) {
    distances_.resize(got);
    for (std::size_t j = 0; j < got; ++j) {
      distances_[j] = (points[ids[j]] - own_).cast<double>().norm();
    }
    for (std::size_t j = 0; j < got; ++j) {
      if (ids[j] != self) offer(points[ids[j]], distances_[j]);
    }
  }

  std::size_t count() const { return kept_.size(); }
  const Eigen::Vector3f& operator[](std::size_t j) const { return kept_[j]; }
  // Distance from the point to neighbour j (increasing in j).
  double distance(std::size_t j) const { return distance_[j]; }
  bool duplicate() const { return duplicate_; }

 private:
  // Neighbours come nearest first: a position stored twice comes twice in a
  // row of equal distances, so only the kept ones at about this distance are
  // compared with it.
  void offer(const Eigen::Vector3f& p, double distance) {
    if (distance <= same_) {
      duplicate_ = true;
      return;
    }
    for (std::size_t j = kept_.size(); j-- > 0 && distance_[j] >= distance - same_;) {
      if ((p - kept_[j]).cast<double>().norm() <= same_) return;
    }
    kept_.push_back(p);
    distance_.push_back(distance);
  }

  Eigen::Vector3f own_;
  double same_ = 0.0;
  std::vector<Eigen::Vector3f> kept_;
  std::vector<double> distance_;
  std::vector<double> distances_;  // offer_all's, of every neighbour
  bool duplicate_ = false;
};

// An organised frame's grid (PointCloud::pixels): a depth camera rounds its
// depths to steps about as deep as its pixels are wide, so a point's nearest
// neighbours in space lie mostly on its own step, and a plane through them
// leans towards the camera. The pixels around its own are the surface's
// neighbours whatever the steps: the plane is fitted to those.
class PixelGrid {
 public:
  // Pixels on each side of a point's own that its window reaches: 5 x 5
  // pixels kept 99.3 % of the real Kinect frame from its sensor (3 x 3: 96.6 %,
  // 7 x 7: 99.3 %; its nearest 16 in space: 98.0 %).
  static constexpr int kReach = 2;
  // The window's points farther than this many times the distance to the
  // point's farthest nearest neighbour are another surface (2: 99.2 %, 3 and
  // 6: 99.3 %; no limit: 99.5 %, but rays between the pixels then leaked
  // through 0.3 % of the frame, at its depth edges).
  static constexpr double kGate = 3.0;

  // `order[s]` is the cloud index of Morton index s.
  PixelGrid(const PointCloud& cloud, const std::vector<std::uint32_t>& order)
      : cloud_(cloud), order_(order) {
    if (!cloud.has_pixels()) return;
    point_.assign(cloud.sensor.width * cloud.sensor.height, kNone);
    for (std::size_t s = 0; s < order.size(); ++s) {
      point_[cloud.pixels[order[s]]] = static_cast<std::uint32_t>(s);
    }
  }

  bool empty() const { return point_.empty(); }

  // The points (Morton indices) of the window around point s's pixel within
  // `reach` of it, but s, nearest to it first.
  void window(std::size_t s, const Eigen::Vector3f* sorted, double reach,
              std::vector<std::uint32_t>& ids) const {
    thread_local std::vector<std::pair<float, std::uint32_t>> found;
    found.clear();
    const auto width = static_cast<std::ptrdiff_t>(cloud_.sensor.width);
    const auto height = static_cast<std::ptrdiff_t>(cloud_.sensor.height);
    const std::uint32_t pixel = cloud_.pixels[order_[s]];
    const std::ptrdiff_t row = pixel / width, column = pixel % width;
    for (std::ptrdiff_t r = std::max<std::ptrdiff_t>(0, row - kReach);
         r <= std::min(height - 1, row + kReach); ++r) {
      for (std::ptrdiff_t c = std::max<std::ptrdiff_t>(0, column - kReach);
           c <= std::min(width - 1, column + kReach); ++c) {
        const std::uint32_t t = point_[static_cast<std::size_t>(r * width + c)];
        if (t == kNone || t == s) continue;
        const Eigen::Vector3f offset = sorted[t] - sorted[s];
        if (offset.cast<double>().norm() > reach) continue;
        found.emplace_back(offset.squaredNorm(), t);
      }
    }
    std::sort(found.begin(), found.end());
    ids.clear();
    for (const auto& entry : found) ids.push_back(entry.second);
  }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  const PointCloud& cloud_;
  const std::vector<std::uint32_t>& order_;
  std::vector<std::uint32_t> point_;  // per pixel, its point's Morton index, or kNone
};

// What distinct_neighbours answers for a point whose nearest, nearest first
// by the same float distance, are ids[0..got) (itself among them): the first
// kSpacingNeighbours of them are a kd-tree's, so the point spacing's sample
// needs no search of its own.
DistinctNeighbour spacing_answer(const Eigen::Vector3f* points, std::size_t self,
                                 const std::uint32_t* ids, std::size_t got, double same) {
  DistinctNeighbour answer{0, std::numeric_limits<float>::infinity()};
  for (std::size_t j = 0; j < std::min<std::size_t>(got, kSpacingNeighbours); ++j) {
    answer.offer(knn_squared_distance(points[self], points[ids[j]]), same);
  }
  return answer;
}

// A plane fitted to the point and its `count` nearest distinct neighbours.
struct PlaneFit {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d major = Eigen::Vector3d::UnitX();  // in-plane axis of the largest spread
  double variation = 1.0;                            // lambda0 / (lambda0 + lambda1 + lambda2)
  double rms = 0.0;     // the points' RMS distance from the plane, sqrt(lambda0)
  double across = 0.0;  // lambda1 / lambda2
  bool spread = false;  // the points span two directions (not a line)
};

PlaneFit fit_plane(const Eigen::Vector3f& own, const Distinct& distinct, std::size_t count) {
  Eigen::Vector3d mean = own.cast<double>();
  for (std::size_t j = 0; j < count; ++j) mean += distinct[j].cast<double>();
  mean /= static_cast<double>(count + 1);
  // The six distinct sums only, each added in the order the full outer
  // products would add it: the same matrix, bit for bit.
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
  const auto add = [&](const Eigen::Vector3f& p) {
    const Eigen::Vector3d d = p.cast<double>() - mean;
    xx += d.x() * d.x();
    xy += d.x() * d.y();
    xz += d.x() * d.z();
    yy += d.y() * d.y();
    yz += d.y() * d.z();
    zz += d.z() * d.z();
  };
  add(own);
  for (std::size_t j = 0; j < count; ++j) add(distinct[j]);
  const double points = static_cast<double>(count + 1);
  Eigen::Matrix3d covariance;
  covariance << xx / points, xy / points, xz / points,  //
      xy / points, yy / points, yz / points,            //
      xz / points, yz / points, zz / points;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  const Eigen::Vector3d lambda = solver.eigenvalues().cwiseMax(0.0);  // increasing
  PlaneFit fit;
  const double total = lambda.sum();
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);
  if (!(total > 0.0) || !normal.allFinite() || !(normal.norm() > 0.5)) return fit;
  fit.normal = normal.normalized();
  const Eigen::Vector3d major = solver.eigenvectors().col(2);
  if (major.allFinite() && major.norm() > 0.5) fit.major = major.normalized();
  fit.variation = lambda[0] / total;
  fit.rms = std::sqrt(lambda[0]);
  fit.spread = lambda[1] >= kMinSpread * lambda[2];
  fit.across = lambda[2] > 0.0 ? lambda[1] / lambda[2] : 0.0;
  return fit;
}

// The noise of the point's surface: its neighbours' distances from its own
// plane, from their lower quartile (a thin object's other side, a minority of
// the neighbours, does not count), scaled to the standard deviation of
// Gaussian noise on both points (|N(0, sigma sqrt 2)| has its quartile at
// 0.45 sigma).
float surface_noise(const Eigen::Vector3f& own, const Distinct& distinct,
                    const Eigen::Vector3d& normal) {
  thread_local std::vector<double> offsets;
  offsets.clear();
  for (std::size_t j = 0; j < distinct.count(); ++j) {
    offsets.push_back(std::abs(normal.dot((distinct[j] - own).cast<double>())));
  }
  const auto quarter = static_cast<std::ptrdiff_t>(offsets.size() / 4);
  std::nth_element(offsets.begin(), offsets.begin() + quarter, offsets.end());
  return static_cast<float>(offsets[static_cast<std::size_t>(quarter)] / 0.45);
}

// The radius rule in the point's tangent plane, where the neighbourhood's
// layout shows (four 90-degree sectors, centred on the plane's two in-plane
// axes):
// - at a surface's boundary some sectors are empty, and the density is the m
//   neighbours over the occupied sectors' share of the disc of radius D, not
//   the whole disc: a boundary point's disc would otherwise be too large by
//   sqrt(2) and overhang the edge;
// - on a regular grid of spacings a x b the surface closes only where r
//   reaches half a cell's diagonal, sqrt(a^2 + b^2) / 2, which the density
//   rule falls short of when b is several times a (a scanner's rows and
//   columns): the neighbourhood's largest spread lies along the rows, so the
//   sectors follow the grid, a and b are the nearest neighbours along each
//   axis (the larger of the two opposite sectors), and r is at least half the
//   diagonal (at most D).
double tangent_radius(const Eigen::Vector3f& own, const Distinct& distinct, const PlaneFit& fit,
                      double farthest, double coverage) {
  const Eigen::Vector3d axis_u = fit.major;
  const Eigen::Vector3d axis_v = fit.normal.cross(axis_u).normalized();
  // Squared, and the root taken once per sector: the root is correctly
  // rounded and monotone, so this is the nearest distance bit for bit, with
  // no root in the loop (its latency was a tenth of the estimate's time).
  // Each neighbour offered to all four sectors, infinitely far from the
  // three it is not in: the sector of a neighbour is a coin toss, and a
  // branch on it or a store to it indexed by it cost more than the rest of
  // the loop.
  double plus_u = INFINITY, plus_v = INFINITY, minus_u = INFINITY, minus_v = INFINITY;
  for (std::size_t j = 0; j < distinct.count(); ++j) {
    const Eigen::Vector3d d = (distinct[j] - own).cast<double>();
    const double u = axis_u.dot(d), v = axis_v.dot(d);
    const double squared = u * u + v * v;
    // squared + 0 where the neighbour is, squared + infinity elsewhere: a
    // table, as a select compiled to a branch.
    static constexpr double kAway[2] = {INFINITY, 0.0};
    const int along_u = std::abs(u) >= std::abs(v) ? 1 : 0;
    const int u_ahead = u >= 0.0 ? 1 : 0, v_ahead = v >= 0.0 ? 1 : 0;
    plus_u = std::min(plus_u, squared + kAway[along_u & u_ahead]);
    minus_u = std::min(minus_u, squared + kAway[along_u & (1 - u_ahead)]);
    plus_v = std::min(plus_v, squared + kAway[(1 - along_u) & v_ahead]);
    minus_v = std::min(minus_v, squared + kAway[(1 - along_u) & (1 - v_ahead)]);
  }
  double nearest[4] = {plus_u, plus_v, minus_u, minus_v};
  for (double& g : nearest) g = std::sqrt(g);
  int occupied = 0;
  for (const double g : nearest) occupied += std::isfinite(g) ? 1 : 0;
  const std::size_t m = distinct.count();
  double radius = coverage_radius(farthest, m, coverage) * std::sqrt(occupied / 4.0);
  const auto gap = [&](int a, int b) {
    const double ga = std::isfinite(nearest[a]) ? nearest[a] : 0.0;
    const double gb = std::isfinite(nearest[b]) ? nearest[b] : 0.0;
    return std::max(ga, gb);
  };
  const double along_axes = 0.5 * std::sqrt(gap(0, 2) * gap(0, 2) + gap(1, 3) * gap(1, 3));
  radius = std::max(radius, std::min(along_axes, farthest));
  return radius;
}

// `distinct` are the point's nearest, which its density is measured from;
// its plane is fitted to `plane_points` (the same, or its pixel window in an
// organised frame).
Neighbourhood measure(const Eigen::Vector3f& own, const Distinct& distinct,
                      const Distinct& plane_points, const SurfelOptions& options) {
  Neighbourhood hood;
  hood.duplicate = distinct.duplicate();
  const std::size_t m = distinct.count();
  if (m == 0) return hood;
  const double farthest = distinct.distance(m - 1);
  hood.radius = static_cast<float>(options.fixed_radius > 0.0
                                       ? options.fixed_radius
                                       : coverage_radius(farthest, m, options.coverage));
  const std::size_t fitted = plane_points.count();
  if (m < kMinNeighbours || fitted < kMinNeighbours) return hood;
  // Near an edge the neighbours lie on two surfaces and the plane through
  // all of them is tilted between both; the nearest half lie mostly on the
  // point's own surface, so where they fit a plane better, theirs is taken.
  PlaneFit fit = fit_plane(own, plane_points, fitted);
  const std::size_t half = std::max(kMinNeighbours, (fitted + 1) / 2);
  if (fit.variation > kFlatVariation && half < fitted) {
    const PlaneFit nearest = fit_plane(own, plane_points, half);
    if (nearest.spread && nearest.variation < fit.variation) fit = nearest;
  }
  hood.surface_variation = static_cast<float>(fit.variation);
  hood.spread = static_cast<float>(fit.across);
  hood.line = !fit.spread;
  if (fit.spread && fit.variation <= options.max_surface_variation) {
    hood.normal = fit.normal.cast<float>();
    // The quartile misses noise that comes in steps (a depth camera's
    // quantised depths put most neighbours on the point's own step): half
    // the RMS distance bounds it from below, and stays below half the gap
    // between a thin board's two sides.
    hood.thickness = std::max(surface_noise(own, plane_points, fit.normal),
                              static_cast<float>(kRmsShare * fit.rms));
    if (options.fixed_radius <= 0.0) {
      hood.radius =
          static_cast<float>(tangent_radius(own, distinct, fit, farthest, options.coverage));
    }
  }
  return hood;
}

// The unit line of sight from the station that measured a point to it, or
// zero where the cloud does not say which station that is.
class LinesOfSight {
 public:
  explicit LinesOfSight(const PointCloud& cloud) : cloud_(cloud), stations_(scan_stations(cloud)) {}

  Eigen::Vector3d of(std::size_t point, const Eigen::Vector3f& position) const {
    const std::ptrdiff_t station = measuring_station(cloud_, stations_.size(), point);
    if (station < 0) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d line =
        position.cast<double>() - stations_[static_cast<std::size_t>(station)].frame.origin;
    const double length = line.norm();
    return length > 0.0 ? Eigen::Vector3d(line / length) : Eigen::Vector3d::Zero();
  }

 private:
  const PointCloud& cloud_;
  std::vector<Station> stations_;
};

// A scanner's range noise lies along its line of sight. Where a point's
// nearest lie along one scan line (near the poles of a laser's sphere its
// rows are far denser than its columns), that noise is their second
// direction of spread, and the fitted plane holds the line of sight: a disc
// edge-on to the station that measured it, which no scanner records (beyond
// about 85 degrees of incidence no return comes back), and which hides its
// neighbours from every other viewpoint. Such a point looks again, with
// kWideSearch times as many neighbours; if its plane still holds the line of
// sight and its neighbours still lie along a line (their spread across is
// below kLineSpread of their spread along), it faces its station. A surface
// truly edge-on to the station (a merged model's, which the station did not
// record) spreads both ways and keeps its plane.
void face_its_station(Neighbourhood& hood, const Eigen::Vector3d& sight, bool widened) {
  if (hood.normal.isZero() || sight.isZero()) return;
  if (std::abs(sight.dot(hood.normal.cast<double>())) >= kMinSightCosine) return;
  if (!widened) {
    hood.line = true;
  } else if (hood.spread < kLineSpread) {
    hood.normal = sight.cast<float>();
  }
}

}  // namespace

double coverage_radius(double farthest_distance, std::size_t distinct_neighbours, double coverage) {
  const double log_open = std::log(1.0 / (1.0 - coverage));
  // One neighbour gives no density estimate: its distance is the best scale there is.
  if (distinct_neighbours < 2) return farthest_distance * std::sqrt(log_open);
  return farthest_distance * std::sqrt(log_open / static_cast<double>(distinct_neighbours - 1));
}

SurfelEstimate estimate_surfels(const PointCloud& cloud, const SurfelOptions& options,
                                const Progress& progress) {
  check_options(cloud, options);
  const auto start = Clock::now();
  const std::size_t count = cloud.size();
  const std::size_t k = std::min(options.neighbours + 1, count);
  // Everything below works on the points in Morton order (index s; the
  // cloud's index is order[s]): the queries, the tree's points and the
  // neighbours each query reads lie together in memory. On a cloud in random
  // order, reading the neighbours' positions was a third of the time.
  if (count > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("surfels: at most 2^32 - 1 points, got " + std::to_string(count));
  }
  const std::vector<std::uint32_t> order = morton_order(cloud.positions, options.threads);
  // Per point, in Morton order.
  // Big arrays in huge pages (core/large_buffer.hpp): on a virtual machine
  // first touching 4 KiB pages one at a time cost a tenth of a 1M cloud's run.
  LargeVector<Eigen::Vector3f> normals(count);
  LargeVector<float> radii(count), variation(count), thickness(count);
  LargeVector<std::uint8_t> duplicate(count), line(count), fitted(count);
  // A disc (not a stray point's sphere) whose normal is its fitted plane's,
  // not its line of sight.
  const auto has_fitted_plane = [&](std::size_t s) { return fitted[s] && !normals[s].isZero(); };
  SurfelEstimate estimate;
  SurfelStats& stats = estimate.stats;
  {
    // The sorted copy and the search's boxes (about 15 bytes a point) live
    // only while searched.
    LargeVector<Eigen::Vector3f> sorted(count);
    parallel_for(count, kGrain * 4, options.threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t s = first; s < last; ++s) sorted[s] = cloud.positions[order[s]];
    });
    const MortonKnn knn(sorted, options.threads);

    // visit(n, s, ids, got) for every point s = subset[n] of `subset` (null:
    // all, s = n) with its `wanted` nearest, nearest first (itself among them).
    const auto search_blocks = [&](const char* stage, const std::vector<std::uint32_t>* subset,
                                   std::size_t wanted, const auto& visit) {
      const std::size_t total = subset ? subset->size() : count;
      const std::size_t block = block_size(total);
      const MortonKnn::Visit each = [&](std::size_t n, std::size_t s, const std::uint32_t* ids,
                                        std::size_t got) { visit(n, s, ids, got); };
      progress(stage, 0.0);
      for (std::size_t begin = 0; begin < total; begin += block) {
        const std::size_t end = std::min(total, begin + block);
        parallel_for(end - begin, kGrain, options.threads,
                     [&](std::size_t first, std::size_t last) {
                       knn.search(subset ? subset->data() : nullptr, begin + first, begin + last,
                                  wanted, each);
                     });
        progress.check_cancel();
        progress(stage, static_cast<double>(end) / static_cast<double>(total));
      }
    };

    const PixelGrid grid(cloud, order);
    const LinesOfSight sight(cloud);
    // The point spacing's sample, answered from this search when it reaches
    // as far as the spacing asks (a point's k nearest hold its
    // kSpacingNeighbours nearest).
    const std::size_t stride = spacing_stride(count);
    std::vector<DistinctNeighbour> spacing_answers;
    if (k >= std::min<std::size_t>(kSpacingNeighbours, count)) {
      spacing_answers.resize((count + stride - 1) / stride);
    }
    const auto model_point = [&](std::size_t, std::size_t s, const std::uint32_t* ids,
                                 std::size_t got) {
      thread_local Distinct distinct, window;
      thread_local std::vector<std::uint32_t> window_ids;
      const Eigen::Vector3f& own = sorted[s];
      const double same = same_position_distance(own);
      distinct.reset(own, same);
      distinct.offer_all(sorted.data(), ids, got, s);
      const Distinct* plane_points = &distinct;
      if (!grid.empty()) {
        // Across a depth edge the window holds the surface behind (or in
        // front): only its points within kGate times the farthest nearest
        // neighbour's distance are taken for the point's surface.
        const double reach = distinct.count() > 0
                                 ? PixelGrid::kGate * distinct.distance(distinct.count() - 1)
                                 : std::numeric_limits<double>::infinity();
        grid.window(s, sorted.data(), reach, window_ids);
        window.reset(own, same);
        window.offer_all(sorted.data(), window_ids.data(), window_ids.size(), s);
        if (window.count() >= kMinNeighbours) plane_points = &window;
      }
      Neighbourhood hood = measure(own, distinct, *plane_points, options);
      if (plane_points == &distinct) {
        face_its_station(hood, sight.of(order[s], own), /*widened=*/got > k);
      }
      if (!spacing_answers.empty() && order[s] % stride == 0) {
        spacing_answers[order[s] / stride] = spacing_answer(sorted.data(), s, ids, got, same);
      }
      normals[s] = hood.normal;
      radii[s] = hood.normal.isZero() ? kSphereShare * hood.radius : hood.radius;
      variation[s] = hood.surface_variation;
      duplicate[s] = hood.duplicate;
      line[s] = hood.line;
      thickness[s] = hood.thickness;
    };
    search_blocks("surfels", nullptr, k, model_point);
    // On a scanner's grid seen at a grazing angle the columns can lie ten
    // times farther apart than the rows, and all k nearest on the point's own
    // scan line: those points look again, kWideSearch times as far in count.
    std::vector<std::uint32_t> lines;
    for (std::size_t s = 0; s < count; ++s) {
      if (line[s]) lines.push_back(static_cast<std::uint32_t>(s));
    }
    search_blocks("surfels (scan lines)", &lines,
                  std::min(kWideSearch * options.neighbours + 1, count), model_point);
    if (!spacing_answers.empty()) estimate.spacing = spacing_from(spacing_answers);
    // A point its station measured but whose neighbours give no plane faces
    // that station: a sphere would stand in front of its neighbours along
    // their own rays by its radius, which the noise of a scanner's densest
    // rows (near its poles) exceeds; a disc as wide as the sphere, facing the
    // station, covers what the sphere covered from there and stands flat.
    parallel_for(count, kGrain * 4, options.threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t s = first; s < last; ++s) {
        fitted[s] = !normals[s].isZero();
        if (!fitted[s]) normals[s] = sight.of(order[s], sorted[s]).cast<float>();
      }
    });

    // Positions stored more than k times have no distinct neighbour in
    // reach: they take the cloud's median radius.
    LargeVector<float> measured;
    measured.reserve(count);
    for (const float r : radii) {
      if (r > 0.0f) measured.push_back(r);
    }
    if (measured.empty()) {
      throw std::invalid_argument(
          "surfels: no point has a neighbour at a distinct position (all points coincide?)");
    }
    const std::vector<float> measured_quantiles = quantiles::in_place(measured, {0.5, 0.1});
    const float median_radius = measured_quantiles[0];
    for (float& r : radii) {
      if (!(r > 0.0f)) r = median_radius;
    }

    if (options.fixed_radius <= 0.0) {
      // Stray points: a radius kStrayRatio times their neighbours' median. A
      // stray point's neighbours are at least as dense as the sparsest tenth
      // of the cloud, so only points above kStrayRatio x that quantile can be
      // stray.
      const float low = measured_quantiles[1];
      std::vector<std::uint32_t> candidates;
      for (std::size_t s = 0; s < count; ++s) {
        if (radii[s] > kStrayRatio * low) candidates.push_back(static_cast<std::uint32_t>(s));
      }
      std::vector<float> stray_radius(candidates.size(), 0.0f);
      search_blocks("stray points", &candidates, k,
                    [&](std::size_t n, std::size_t s, const std::uint32_t* ids, std::size_t got) {
                      thread_local std::vector<float> around;
                      around.clear();
                      for (std::size_t j = 0; j < got; ++j) {
                        if (ids[j] != s) around.push_back(radii[ids[j]]);
                      }
                      if (around.empty()) return;
                      const float typical = quantiles::at(around, 0.5);
                      if (radii[s] > kStrayRatio * typical) stray_radius[n] = typical;
                    });
      for (std::size_t n = 0; n < candidates.size(); ++n) {
        if (!(stray_radius[n] > 0.0f)) continue;
        const std::size_t s = candidates[n];
        radii[s] = stray_radius[n];
        normals[s] = Eigen::Vector3f::Zero();
        thickness[s] = 0.0f;
        ++stats.stray;
      }
    }
  }

  stats.points = count;
  {
    LargeVector<float> oriented_variation, oriented_thickness;
    oriented_variation.reserve(count);
    oriented_thickness.reserve(count);
    for (std::size_t s = 0; s < count; ++s) {
      stats.duplicates += duplicate[s];
      stats.facing_station += !fitted[s] && !normals[s].isZero();
      // Over the discs whose plane was fitted: one that faces its station
      // measured no thickness (nor a plane's variation).
      if (has_fitted_plane(s)) {
        oriented_variation.push_back(variation[s]);
        oriented_thickness.push_back(thickness[s]);
      }
    }
    stats.oriented = oriented_variation.size();
    stats.unoriented = count - stats.oriented;
    // Three selections over a million values each, apart: one a thread.
    LargeVector<float> radius_order = radii;
    parallel_for(3, 1, options.threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t task = first; task < last; ++task) {
        if (task == 0) {
          stats.surface_variation_median = quantiles::at(oriented_variation, 0.5);
        } else if (task == 1) {
          stats.thickness_median = quantiles::at(oriented_thickness, 0.5);
        } else {
          const std::vector<float> q = quantiles::in_place(radius_order, {0.1, 0.5, 0.9});
          stats.radius_quantile_10 = q[0];
          stats.radius_median = q[1];
          stats.radius_quantile_90 = q[2];
        }
      }
    });
  }
  // Freed (`v = {}` would keep their memory) before the surfels are made: a
  // big cloud's peak was there.
  release(variation);
  release(duplicate);
  release(line);
  if (!options.keep_thickness) release(thickness);

  // Back in the cloud's order.
  estimate.surfels.resize(count);
  if (options.keep_thickness) estimate.thickness.resize(count);
  std::vector<std::uint8_t> measured(options.keep_thickness ? count : 0);
  parallel_for(count, kGrain * 4, options.threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t s = first; s < last; ++s) {
      const std::size_t i = order[s];
      estimate.surfels[i] = make_surfel(cloud.positions[i], normals[s], radii[s], i);
      if (options.keep_thickness) {
        estimate.thickness[i] = thickness[s];
        measured[i] = has_fitted_plane(s);
      }
    }
  });
  release(fitted);
  if (options.keep_thickness) {
    estimate.beam_order = find_beam_order(cloud, scan_stations(cloud));
    estimate.noise = measure_surface_noise(cloud, estimate.surfels, estimate.thickness, measured,
                                           estimate.beam_order);
    if (options.carve_sight_lines) {
      estimate.carving = carve_sight_lines(cloud, estimate, options.threads, progress);
    }
  }
  stats.seconds = seconds_since(start);
  progress("surfels", 1.0);
  return estimate;
}

}  // namespace occlusion
