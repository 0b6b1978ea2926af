#include "occlusion/analysis/station_visibility.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include "analysis_support.hpp"
#include "occlusion/analysis/scan_tracer.hpp"
#include "occlusion/core/morton_order.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

namespace {

constexpr char kAnalysis[] = "station visibility";

// Rays between two progress reports, and between two cancel checks of a
// thread: a few milliseconds of tracing, as -moc and -fscan check. A
// candidate's rays to a million targets take seconds, so checking once per
// candidate left a Ctrl-C in Python (which a report polls) 5-14 s late.
constexpr std::size_t kRaysPerReport = std::size_t{1} << 16;
// Targets per block traced on one thread: a patch of surface (the targets
// are in Morton order), one window of the octree's batch (ray_order.hpp).
constexpr std::size_t kTargetsPerThreadBlock = 4096;
// Targets per block traced on all threads (few candidates): bounds the scratch
// memory; cancel is checked and progress reported after each.
constexpr std::size_t kTargetsPerSharedBlock = std::size_t{1} << 16;

double radians(double degrees) {
  return degrees * M_PI / 180.0;
}

void check_candidates(const std::vector<Eigen::Vector3d>& candidates) {
  if (candidates.empty()) throw std::invalid_argument("station visibility: no candidate stations");
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!candidates[c].allFinite()) {
      throw std::invalid_argument("station visibility: candidate " + std::to_string(c) +
                                  " is not finite");
    }
  }
}

// The weights, once checked: one per target, finite and >= 0.
std::vector<double> checked_weights(std::vector<double> weight, std::size_t targets,
                                    const char* what) {
  if (weight.size() != targets) {
    throw std::invalid_argument("station visibility: " + std::to_string(weight.size()) +
                                " target weights for " + std::to_string(targets) + " " + what);
  }
  for (std::size_t t = 0; t < weight.size(); ++t) {
    if (!std::isfinite(weight[t]) || weight[t] < 0.0) {
      throw std::invalid_argument("station visibility: the weight of target " + std::to_string(t) +
                                  " is negative or not finite");
    }
  }
  return weight;
}

// The cloud, once its point model is checked.
const PointCloud& checked_cloud(const PointCloud& cloud, const ScanOptions& options) {
  cloud.validate();
  if (cloud.size() == 0) throw std::invalid_argument("station visibility: the cloud has no points");
  if (options.field_of_view) {
    throw std::invalid_argument(
        "station visibility: a candidate station turns all the way round; a laser station's "
        "field of view does not apply to it");
  }
  if (!std::isfinite(options.self_tolerance)) {
    throw std::invalid_argument("station visibility: self_tolerance must be a finite number");
  }
  analysis_support::check_point_model(cloud, {}, options.point_radius, options.surfels, kAnalysis);
  return cloud;
}

// The candidates, where float still resolves the point model.
void check_cloud_candidates(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& candidates,
                            const ScanOptions& options) {
  check_candidates(candidates);
  analysis_support::check_point_model(cloud, candidates, options.point_radius, options.surfels,
                                      kAnalysis);
}

// The mesh, once checked.
const TriangleMesh& checked_mesh(const TriangleMesh& mesh, const MeshOcclusionOptions& options) {
  mesh.validate();
  if (mesh.faces.empty()) throw std::invalid_argument("station visibility: the mesh has no faces");
  analysis_support::check_positive(options.epsilon_scale, "epsilon_scale", kAnalysis);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  if (!((hi - lo).norm() > 0.0)) {
    throw std::invalid_argument("station visibility: the mesh has zero extent");
  }
  return mesh;
}

// The candidates, where float still resolves the mesh seen from them (as
// compute_mesh_occlusion checks its viewpoints).
void check_mesh_candidates(const TriangleMesh& mesh,
                           const std::vector<Eigen::Vector3d>& candidates) {
  check_candidates(candidates);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  const Eigen::Vector3d origin = 0.5 * (lo + hi);
  std::vector<Eigen::Vector3d> local;
  for (const auto& candidate : candidates) local.push_back(candidate - origin);
  analysis_support::check_float_precision(
      (lo - origin).cast<float>(), (hi - origin).cast<float>(), local,
      {(hi - lo).norm(), "the mesh's diagonal", "the mesh's centre", "mesh"}, kAnalysis);
}

void check_samples(const TriangleMesh& mesh, const MeshSamples& samples) {
  if (samples.face.size() != samples.points.size()) {
    throw std::invalid_argument("station visibility: " + std::to_string(samples.face.size()) +
                                " sample faces for " + std::to_string(samples.points.size()) +
                                " samples");
  }
  for (std::size_t s = 0; s < samples.size(); ++s) {
    if (samples.face[s] >= mesh.face_count()) {
      throw std::invalid_argument("station visibility: sample " + std::to_string(s) +
                                  " lies on face " + std::to_string(samples.face[s]) +
                                  ", which the mesh does not have");
    }
  }
}

// The targets worth tracing (weight > 0) in Morton order of their
// positions: a block of them is a patch of surface, so one candidate's rays
// to it point nearly the same way and trace as packets. Reported as stage
// "ordering targets": with the copies around it, seconds for tens of
// millions of targets, so cancel is checked between the steps.
std::vector<std::uint32_t> coherent_targets(const std::vector<Eigen::Vector3f>& positions,
                                            const std::vector<double>& weight,
                                            const Progress& progress) {
  progress.check_cancel();
  progress("ordering targets", 0.0);
  std::vector<std::uint32_t> order = morton_order(positions);
  progress.check_cancel();
  progress("ordering targets", 0.5);
  order.erase(std::remove_if(order.begin(), order.end(),
                             [&](std::uint32_t target) { return !(weight[target] > 0.0); }),
              order.end());
  return order;
}

// Scratch for one block of one candidate's rays.
struct RayBlock {
  std::vector<Ray> rays;
  std::vector<PrimitiveId> ignore;
  std::vector<std::uint32_t> target;
  std::vector<std::uint8_t> blocked;
  explicit RayBlock(std::size_t size) : rays(size), ignore(size), target(size), blocked(size) {}
};

// Sets the bits of the targets (of `order`) each candidate sees.
// make_all(station, first, last, rays) makes the rays of targets order[first
// .. last) in one go, ignoring each its own primitive (order[k] is its id), or
// returns false where it cannot: then admits(station, k) applies the limits to
// target order[k], and make(station, k, ray, ignore) makes its shadow ray, or
// returns false for a target seen without one. occluded(rays, count, ignore,
// blocked, threads) traces them.
// Many candidates: each thread fills whole rows, one candidate at a time, its
// rays traced on that thread (no two threads write one row). Few: one
// candidate at a time, its blocks traced on every thread.
template <class MakeAll, class Admits, class Make, class Occluded>
void fill_rows(CoverageMatrix& matrix, const std::vector<Eigen::Vector3d>& candidates,
               const std::vector<std::uint32_t>& order, unsigned threads, const Progress& progress,
               const MakeAll& make_all, const Admits& admits, const Make& make,
               const Occluded& occluded) {
  static_assert(sizeof(PrimitiveId) == sizeof(std::uint32_t), "target indices are primitive ids");
  const auto trace_block = [&](std::size_t c, std::size_t first, std::size_t last,
                               unsigned block_threads, RayBlock& block) {
    const Eigen::Vector3d& station = candidates[c];
    std::size_t count = 0;
    const std::uint32_t* target = block.target.data();
    const PrimitiveId* ignore = block.ignore.data();
    if (make_all(station, first, last, block.rays.data())) {
      count = last - first;
      target = ignore = order.data() + first;
    } else {
      for (std::size_t k = first; k < last; ++k) {
        if (!admits(station, k)) continue;
        if (!make(station, k, block.rays[count], block.ignore[count])) {
          matrix.set_seen(c, order[k]);
          continue;
        }
        block.target[count++] = order[k];
      }
    }
    occluded(block.rays.data(), count, ignore, block.blocked.data(), block_threads);
    for (std::size_t k = 0; k < count; ++k) {
      if (!block.blocked[k]) matrix.set_seen(c, target[k]);
    }
  };
  const std::size_t n = candidates.size();
  const unsigned workers = resolve_thread_count(threads);
  // Rays counted as targets of each candidate, whether or not a limit drops them.
  const double total = std::max(1.0, static_cast<double>(n) * static_cast<double>(order.size()));
  progress("tracing", 0.0);
  if (n >= 2 * std::size_t{workers}) {
    // Candidates are handed out one at a time with no barrier between them
    // (their costs differ: one inside furniture is blocked at once); every
    // thread checks cancel after each block, and the calling thread, one of
    // the workers, reports.
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<std::size_t> traced{0};
    std::size_t next_report = kRaysPerReport;
    const auto after_block = [&](std::size_t rays) {
      const std::size_t done = traced.fetch_add(rays) + rays;
      progress.check_cancel();
      if (done >= next_report && std::this_thread::get_id() == caller) {
        next_report = done + kRaysPerReport;
        progress("tracing", static_cast<double>(done) / total);
      }
    };
    parallel_for(n, 1, threads, [&](std::size_t b, std::size_t e) {
      RayBlock block(std::min(order.size(), kTargetsPerThreadBlock));
      for (std::size_t c = b; c < e; ++c) {
        for (std::size_t k = 0; k < order.size(); k += kTargetsPerThreadBlock) {
          const std::size_t last = std::min(order.size(), k + kTargetsPerThreadBlock);
          trace_block(c, k, last, 1, block);
          after_block(last - k);
        }
        progress.check_cancel();
      }
    });
    progress("tracing", 1.0);
    return;
  }
  RayBlock block(std::min(order.size(), kTargetsPerSharedBlock));
  for (std::size_t c = 0; c < n; ++c) {
    for (std::size_t k = 0; k < order.size(); k += kTargetsPerSharedBlock) {
      const std::size_t last = std::min(order.size(), k + kTargetsPerSharedBlock);
      trace_block(c, k, last, threads, block);
      progress.check_cancel();
      progress("tracing", (static_cast<double>(c) * static_cast<double>(order.size()) +
                           static_cast<double>(last)) /
                              total);
    }
    progress.check_cancel();
  }
  progress("tracing", 1.0);
}

// The pairs (i < j) of candidates, traced through `occluded` in blocks; what
// make(i, j, ray) declines (false) is seen without a ray.
std::vector<std::uint8_t> candidate_pairs(
    std::size_t n, const Progress& progress,
    const std::function<bool(std::size_t i, std::size_t j, Ray& ray)>& make,
    const std::function<void(const Ray*, std::size_t, std::uint8_t*)>& occluded) {
  std::vector<std::uint8_t> sees(n * n, 0);
  for (std::size_t i = 0; i < n; ++i) sees[i * n + i] = 1;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<Ray> rays;
  std::vector<std::uint8_t> blocked;
  const auto flush = [&] {
    blocked.resize(rays.size());
    occluded(rays.data(), rays.size(), blocked.data());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::uint8_t seen = blocked[k] ? 0 : 1;
      sees[pairs[k].first * n + pairs[k].second] = seen;
      sees[pairs[k].second * n + pairs[k].first] = seen;
    }
    pairs.clear();
    rays.clear();
    progress.check_cancel();
  };
  progress("intervisibility", 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      Ray ray;
      if (!make(i, j, ray)) {
        sees[i * n + j] = sees[j * n + i] = 1;
        continue;
      }
      rays.push_back(ray);
      pairs.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
      if (rays.size() == kTargetsPerSharedBlock) flush();
    }
    progress("intervisibility", static_cast<double>(i + 1) / static_cast<double>(n));
  }
  flush();
  return sees;
}

}  // namespace

std::vector<Eigen::Vector3f> face_unit_normals(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3f> normals(mesh.face_count(), Eigen::Vector3f::Zero());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto& v = mesh.faces[f];
    const Eigen::Vector3d n = (mesh.vertices[v[1]] - mesh.vertices[v[0]])
                                  .cross(mesh.vertices[v[2]] - mesh.vertices[v[0]]);
    if (n.norm() > 0.0) normals[f] = n.normalized().cast<float>();
  }
  return normals;
}

StationLimitTest::StationLimitTest(const StationLimits& limits) {
  const auto refuse = [](const std::string& what) {
    throw std::invalid_argument("station visibility: " + what);
  };
  if (!std::isfinite(limits.max_range) || limits.max_range < 0.0) {
    refuse("max_range must be a finite number >= 0 (0: no limit)");
  }
  if (!std::isfinite(limits.max_incidence_deg) || limits.max_incidence_deg < 0.0 ||
      limits.max_incidence_deg > 90.0) {
    refuse("max_incidence_deg must lie in [0, 90] (0: no limit)");
  }
  if (!(limits.min_elevation_deg >= -90.0 && limits.min_elevation_deg <= 90.0 &&
        limits.max_elevation_deg >= -90.0 && limits.max_elevation_deg <= 90.0)) {
    refuse("the elevation limits must lie in [-90, 90] degrees");
  }
  if (limits.min_elevation_deg > limits.max_elevation_deg) {
    refuse("min_elevation_deg " + std::to_string(limits.min_elevation_deg) +
           " is above max_elevation_deg " + std::to_string(limits.max_elevation_deg));
  }
  if (!limits.up.allFinite() || !(limits.up.norm() > 0.0)) {
    refuse("the up axis must be a finite, non-zero vector");
  }
  if (limits.max_range > 0.0) max_range_squared_ = limits.max_range * limits.max_range;
  if (limits.max_incidence_deg > 0.0) {
    incidence_ = true;
    min_cos_incidence_ = std::cos(radians(limits.max_incidence_deg));
  }
  if (limits.min_elevation_deg > -90.0 || limits.max_elevation_deg < 90.0) {
    elevation_ = true;
    sin_min_elevation_ = std::sin(radians(limits.min_elevation_deg));
    sin_max_elevation_ = std::sin(radians(limits.max_elevation_deg));
  }
  up_ = limits.up.normalized();
  unlimited_ = max_range_squared_ == 0.0 && !incidence_ && !elevation_;
}

bool StationLimitTest::admits(const Eigen::Vector3d& to_target,
                              const Eigen::Vector3f& normal) const {
  if (unlimited_) return true;
  const double squared = to_target.squaredNorm();
  if (max_range_squared_ > 0.0 && squared > max_range_squared_) return false;
  const double length = std::sqrt(squared);
  if (!(length > 0.0)) return true;  // a target at the station
  if (elevation_) {
    const double sine = up_.dot(to_target) / length;
    if (sine < sin_min_elevation_ || sine > sin_max_elevation_) return false;
  }
  if (incidence_ && (normal.x() != 0.0f || normal.y() != 0.0f || normal.z() != 0.0f)) {
    const double cosine = std::abs(normal.cast<double>().dot(to_target)) / length;
    if (cosine < min_cos_incidence_) return false;
  }
  return true;
}

CloudStationVisibility::CloudStationVisibility(const PointCloud& cloud,
                                               std::vector<double> target_weight,
                                               const ScanOptions& options,
                                               const StationLimits& limits,
                                               const Progress& progress)
    : cloud_(checked_cloud(cloud, options)),
      options_(options),
      weight_(checked_weights(std::move(target_weight), cloud.size(), "points")),
      limits_(limits),
      tracer_(cloud, options, progress) {
  // The points' discs copied in the order they are traced, for every
  // candidate to read as one stream.
  order_ = coherent_targets(cloud.positions, weight_, progress);
  targets_.resize(order_.size());
  for (std::size_t k = 0; k < order_.size(); ++k) targets_[k] = tracer_.target(order_[k]);
  progress.check_cancel();
  progress("ordering targets", 1.0);
}

CoverageMatrix CloudStationVisibility::coverage(const std::vector<Eigen::Vector3d>& candidates,
                                                const Progress& progress) const {
  check_cloud_candidates(cloud_, candidates, options_);
  CoverageMatrix matrix(candidates.size(), weight_);
  fill_rows(
      matrix, candidates, order_, options_.threads, progress,
      [&](const Eigen::Vector3d& station, std::size_t first, std::size_t last, Ray* rays) {
        if (!limits_.unlimited()) return false;
        tracer_.rays(station, targets_.data() + first, last - first, rays);
        return true;
      },
      [&](const Eigen::Vector3d& station, std::size_t k) {
        return limits_.admits_point(station, targets_[k]);
      },
      [&](const Eigen::Vector3d& station, std::size_t k, Ray& ray, PrimitiveId& ignore) {
        ray = tracer_.ray(station, targets_[k]);
        ignore = order_[k];
        return true;
      },
      [&](const Ray* rays, std::size_t count, const PrimitiveId* ignore, std::uint8_t* blocked,
          unsigned threads) {
        // A block of targets in Morton order is a patch of surface: its rays
        // from one candidate are coherent as they come.
        tracer_.occluded(rays, count, ignore, blocked, threads, BatchOrder::kAsGiven);
      });
  progress("done", 1.0);
  return matrix;
}

std::vector<std::uint8_t> CloudStationVisibility::intervisibility(
    const std::vector<Eigen::Vector3d>& candidates, const Progress& progress) const {
  check_cloud_candidates(cloud_, candidates, options_);
  return candidate_pairs(
      candidates.size(), progress,
      [&](std::size_t i, std::size_t j, Ray& ray) {
        ray = tracer_.segment(candidates[i], candidates[j]);
        return true;
      },
      [&](const Ray* rays, std::size_t count, std::uint8_t* blocked) {
        tracer_.occluded(rays, count, nullptr, blocked, options_.threads);
      });
}

MeshStationVisibility::MeshStationVisibility(const TriangleMesh& mesh, const MeshSamples& samples,
                                             std::vector<double> target_weight,
                                             const MeshOcclusionOptions& options,
                                             const StationLimits& limits, const Progress& progress)
    : mesh_(checked_mesh(mesh, options)),
      samples_(samples),
      options_(options),
      weight_(checked_weights(std::move(target_weight), samples.size(), "samples")),
      limits_(limits) {
  check_samples(mesh, samples);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  origin_ = 0.5 * (lo + hi);
  // Every sample lies within one diagonal of every face, so nothing that can
  // block a shadow ray is farther away than that.
  reach_ = 2.0 * (hi - lo).norm();
  epsilon_ = mesh_shadow_epsilon(mesh, options);
  progress("building octree", 0.0);
  tree_ = TriangleOctree(pack_triangles(mesh, origin_), options.octree, progress);
  progress.check_cancel();
  normals_ = face_unit_normals(mesh);
  std::vector<Eigen::Vector3f> positions(samples.size());
  for (std::size_t s = 0; s < samples.size(); ++s) positions[s] = samples.points[s].cast<float>();
  order_ = coherent_targets(positions, weight_, progress);
  ordered_.resize(order_.size());
  for (std::size_t k = 0; k < order_.size(); ++k) {
    ordered_[k] = {samples.points[order_[k]] - origin_, samples.face[order_[k]]};
  }
  progress.check_cancel();
  progress("ordering targets", 1.0);
}

CoverageMatrix MeshStationVisibility::coverage(const std::vector<Eigen::Vector3d>& candidates,
                                               const Progress& progress) const {
  check_mesh_candidates(mesh_, candidates);
  CoverageMatrix matrix(candidates.size(), weight_);
  fill_rows(
      matrix, candidates, order_, options_.threads, progress,
      [](const Eigen::Vector3d&, std::size_t, std::size_t, Ray*) { return false; },
      [&](const Eigen::Vector3d& station, std::size_t k) {
        return limits_.admits(samples_.points[order_[k]] - station, normals_[ordered_[k].face]);
      },
      [&](const Eigen::Vector3d& station, std::size_t k, Ray& ray, PrimitiveId& ignore) {
        ignore = ordered_[k].face;
        return mesh_shadow_ray(ordered_[k].local, station - origin_, epsilon_, ray, reach_);
      },
      [&](const Ray* rays, std::size_t count, const PrimitiveId* ignore, std::uint8_t* blocked,
          unsigned threads) {
        tree_.occluded_batch(rays, count, ignore, blocked, threads, BatchOrder::kAsGiven);
      });
  progress("done", 1.0);
  return matrix;
}

std::vector<std::uint8_t> MeshStationVisibility::intervisibility(
    const std::vector<Eigen::Vector3d>& candidates, const Progress& progress) const {
  check_mesh_candidates(mesh_, candidates);
  return candidate_pairs(
      candidates.size(), progress,
      [&](std::size_t i, std::size_t j, Ray& ray) {
        return mesh_shadow_ray(candidates[j] - origin_, candidates[i] - origin_, epsilon_, ray,
                               reach_);
      },
      [&](const Ray* rays, std::size_t count, std::uint8_t* blocked) {
        tree_.occluded_batch(rays, count, nullptr, blocked, options_.threads);
      });
}

CoverageMatrix cloud_station_coverage(const PointCloud& cloud,
                                      const std::vector<Eigen::Vector3d>& candidates,
                                      std::vector<double> target_weight, const ScanOptions& options,
                                      const StationLimits& limits, const Progress& progress) {
  check_cloud_candidates(checked_cloud(cloud, options), candidates, options);
  return CloudStationVisibility(cloud, std::move(target_weight), options, limits, progress)
      .coverage(candidates, progress);
}

CoverageMatrix mesh_station_coverage(const TriangleMesh& mesh, const MeshSamples& samples,
                                     const std::vector<Eigen::Vector3d>& candidates,
                                     std::vector<double> target_weight,
                                     const MeshOcclusionOptions& options,
                                     const StationLimits& limits, const Progress& progress) {
  check_mesh_candidates(checked_mesh(mesh, options), candidates);
  return MeshStationVisibility(mesh, samples, std::move(target_weight), options, limits, progress)
      .coverage(candidates, progress);
}

std::vector<std::uint8_t> cloud_candidate_intervisibility(
    const PointCloud& cloud, const std::vector<Eigen::Vector3d>& candidates,
    const ScanOptions& options, const Progress& progress) {
  check_cloud_candidates(checked_cloud(cloud, options), candidates, options);
  // Weight 0 everywhere: only the octree is built.
  return CloudStationVisibility(cloud, std::vector<double>(cloud.size(), 0.0), options, {},
                                progress)
      .intervisibility(candidates, progress);
}

std::vector<std::uint8_t> mesh_candidate_intervisibility(
    const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& candidates,
    const MeshOcclusionOptions& options, const Progress& progress) {
  check_mesh_candidates(checked_mesh(mesh, options), candidates);
  // No samples: only the octree is built.
  const MeshSamples none{{}, {}, {0}};
  return MeshStationVisibility(mesh, none, {}, options, {}, progress)
      .intervisibility(candidates, progress);
}

}  // namespace occlusion
