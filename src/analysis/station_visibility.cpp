#include "occlusion/analysis/station_visibility.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "analysis_support.hpp"
#include "occlusion/analysis/scan_tracer.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

namespace {

constexpr char kAnalysis[] = "station visibility";

// Targets per traced block: bounds the scratch memory and sets how often
// progress and cancel are checked.
constexpr std::size_t kTargetsPerBlock = std::size_t{1} << 16;

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

void check_weights(const std::vector<double>& weight, std::size_t targets, const char* what) {
  if (weight.size() != targets) {
    throw std::invalid_argument("station visibility: " + std::to_string(weight.size()) +
                                " target weights for " + std::to_string(targets) + " " + what);
  }
}

void check_cloud_inputs(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& candidates,
                        const ScanOptions& options) {
  cloud.validate();
  if (cloud.size() == 0) throw std::invalid_argument("station visibility: the cloud has no points");
  check_candidates(candidates);
  if (options.field_of_view) {
    throw std::invalid_argument(
        "station visibility: a candidate station turns all the way round; a laser station's "
        "field of view does not apply to it");
  }
  if (!std::isfinite(options.self_tolerance)) {
    throw std::invalid_argument("station visibility: self_tolerance must be a finite number");
  }
  analysis_support::check_point_model(cloud, candidates, options.point_radius, options.surfels,
                                      kAnalysis);
}

// The frame -moc traces a mesh in (compute_mesh_occlusion): around the
// centre of its bounds, so that float keeps its precision far from the
// origin, with shadow rays longer than `reach` cut from the sample's end.
struct MeshFrame {
  Eigen::Vector3d origin;
  double reach = 0.0;
  double epsilon = 0.0;
};

MeshFrame mesh_frame(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& candidates,
                     const MeshOcclusionOptions& options) {
  mesh.validate();
  if (mesh.faces.empty()) throw std::invalid_argument("station visibility: the mesh has no faces");
  check_candidates(candidates);
  analysis_support::check_positive(options.epsilon_scale, "epsilon_scale", kAnalysis);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  MeshFrame frame;
  frame.origin = 0.5 * (lo + hi);
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0.0)) {
    throw std::invalid_argument("station visibility: the mesh has zero extent");
  }
  std::vector<Eigen::Vector3d> local;
  for (const auto& candidate : candidates) local.push_back(candidate - frame.origin);
  analysis_support::check_float_precision(
      (lo - frame.origin).cast<float>(), (hi - frame.origin).cast<float>(), local,
      {diagonal, "the mesh's diagonal", "the mesh's centre", "mesh"}, kAnalysis);
  frame.reach = 2.0 * diagonal;
  frame.epsilon = mesh_shadow_epsilon(mesh, options);
  return frame;
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

// One candidate's targets, block by block: those with weight and inside the
// limits go to `trace(first_of_block, targets, count)`, which sets their bits.
void for_each_admitted_block(
    std::size_t targets, const std::vector<double>& weight, const Progress& progress,
    const std::function<bool(std::size_t target)>& admits,
    const std::function<void(const std::uint32_t* targets, std::size_t count)>& trace) {
  std::vector<std::uint32_t> admitted;
  admitted.reserve(std::min(targets, kTargetsPerBlock));
  for (std::size_t first = 0; first < targets; first += kTargetsPerBlock) {
    const std::size_t last = std::min(targets, first + kTargetsPerBlock);
    admitted.clear();
    for (std::size_t t = first; t < last; ++t) {
      if (weight[t] > 0.0 && admits(t)) admitted.push_back(static_cast<std::uint32_t>(t));
    }
    trace(admitted.data(), admitted.size());
    progress.check_cancel();
  }
}

// The pairs (i < j) of candidates, traced through `occluded` in blocks; what
// make(i, j, ray) declines (false) is seen without a ray.
std::vector<std::uint8_t> intervisibility(
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
      if (rays.size() == kTargetsPerBlock) flush();
    }
    progress("intervisibility", static_cast<double>(i + 1) / static_cast<double>(n));
  }
  flush();
  return sees;
}

std::vector<Eigen::Vector3f> face_normals(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3f> normals(mesh.face_count(), Eigen::Vector3f::Zero());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto& v = mesh.faces[f];
    const Eigen::Vector3d n = (mesh.vertices[v[1]] - mesh.vertices[v[0]])
                                  .cross(mesh.vertices[v[2]] - mesh.vertices[v[0]]);
    if (n.norm() > 0.0) normals[f] = n.normalized().cast<float>();
  }
  return normals;
}

}  // namespace

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

CoverageMatrix cloud_station_coverage(const PointCloud& cloud,
                                      const std::vector<Eigen::Vector3d>& candidates,
                                      std::vector<double> target_weight, const ScanOptions& options,
                                      const StationLimits& limits, const Progress& progress) {
  check_cloud_inputs(cloud, candidates, options);
  check_weights(target_weight, cloud.size(), "points");
  const StationLimitTest limit_test(limits);
  CoverageMatrix matrix(candidates.size(), std::move(target_weight));

  progress("building octree", 0.0);
  const ScanTracer tracer(cloud, options, progress);
  progress.check_cancel();

  const std::size_t block = std::min(cloud.size(), kTargetsPerBlock);
  std::vector<Ray> rays(block);
  std::vector<std::uint8_t> blocked(block), seen(block);
  const Eigen::Vector3f no_normal = Eigen::Vector3f::Zero();
  progress("tracing", 0.0);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const Eigen::Vector3d& station = candidates[c];
    for_each_admitted_block(
        cloud.size(), matrix.target_weight(), progress,
        [&](std::size_t point) {
          const Eigen::Vector3f& normal =
              options.surfels ? options.surfels->surfels[point].normal : no_normal;
          return limit_test.admits(cloud.positions[point].cast<double>() - station, normal);
        },
        [&](const std::uint32_t* points, std::size_t count) {
          tracer.trace(station, points, count, seen.data(), rays.data(), blocked.data());
          for (std::size_t k = 0; k < count; ++k) {
            if (seen[k]) matrix.set_seen(c, points[k]);
          }
        });
    progress("tracing", static_cast<double>(c + 1) / static_cast<double>(candidates.size()));
  }
  progress("done", 1.0);
  return matrix;
}

CoverageMatrix mesh_station_coverage(const TriangleMesh& mesh, const MeshSamples& samples,
                                     const std::vector<Eigen::Vector3d>& candidates,
                                     std::vector<double> target_weight,
                                     const MeshOcclusionOptions& options,
                                     const StationLimits& limits, const Progress& progress) {
  const MeshFrame frame = mesh_frame(mesh, candidates, options);
  check_samples(mesh, samples);
  check_weights(target_weight, samples.size(), "samples");
  const StationLimitTest limit_test(limits);
  CoverageMatrix matrix(candidates.size(), std::move(target_weight));
  const std::vector<Eigen::Vector3f> normals = face_normals(mesh);

  progress("building octree", 0.0);
  const TriangleOctree tree(pack_triangles(mesh, frame.origin), options.octree, progress);
  progress.check_cancel();

  const std::size_t block = std::min(samples.size(), kTargetsPerBlock);
  std::vector<Ray> rays(block);
  std::vector<PrimitiveId> ignore(block);
  std::vector<std::uint32_t> traced(block);
  std::vector<std::uint8_t> blocked(block);
  progress("tracing", 0.0);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const Eigen::Vector3d& station = candidates[c];
    const Eigen::Vector3d local_station = station - frame.origin;
    for_each_admitted_block(
        samples.size(), matrix.target_weight(), progress,
        [&](std::size_t s) {
          return limit_test.admits(samples.points[s] - station, normals[samples.face[s]]);
        },
        [&](const std::uint32_t* targets, std::size_t count) {
          std::size_t ray_count = 0;
          for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t s = targets[k];
            if (!mesh_shadow_ray(samples.points[s] - frame.origin, local_station, frame.epsilon,
                                 rays[ray_count], frame.reach)) {
              matrix.set_seen(c, s);  // too close to need a ray
              continue;
            }
            ignore[ray_count] = samples.face[s];
            traced[ray_count++] = s;
          }
          tree.occluded_batch(rays.data(), ray_count, ignore.data(), blocked.data(),
                              options.threads);
          for (std::size_t k = 0; k < ray_count; ++k) {
            if (!blocked[k]) matrix.set_seen(c, traced[k]);
          }
        });
    progress("tracing", static_cast<double>(c + 1) / static_cast<double>(candidates.size()));
  }
  progress("done", 1.0);
  return matrix;
}

std::vector<std::uint8_t> cloud_candidate_intervisibility(
    const PointCloud& cloud, const std::vector<Eigen::Vector3d>& candidates,
    const ScanOptions& options, const Progress& progress) {
  check_cloud_inputs(cloud, candidates, options);
  progress("building octree", 0.0);
  const ScanTracer tracer(cloud, options, progress);
  return intervisibility(
      candidates.size(), progress,
      [&](std::size_t i, std::size_t j, Ray& ray) {
        ray = tracer.segment(candidates[i], candidates[j]);
        return true;
      },
      [&](const Ray* rays, std::size_t count, std::uint8_t* blocked) {
        tracer.occluded(rays, count, nullptr, blocked);
      });
}

std::vector<std::uint8_t> mesh_candidate_intervisibility(
    const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& candidates,
    const MeshOcclusionOptions& options, const Progress& progress) {
  const MeshFrame frame = mesh_frame(mesh, candidates, options);
  progress("building octree", 0.0);
  const TriangleOctree tree(pack_triangles(mesh, frame.origin), options.octree, progress);
  return intervisibility(
      candidates.size(), progress,
      [&](std::size_t i, std::size_t j, Ray& ray) {
        return mesh_shadow_ray(candidates[j] - frame.origin, candidates[i] - frame.origin,
                               frame.epsilon, ray, frame.reach);
      },
      [&](const Ray* rays, std::size_t count, std::uint8_t* blocked) {
        tree.occluded_batch(rays, count, nullptr, blocked, options.threads);
      });
}

}  // namespace occlusion
