#include "occlusion/analysis/station_view.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "analysis_support.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/parallel.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;

// Rays made per task: enough to outweigh handing out the task.
constexpr std::size_t kRayGrain = 4096;

void check_position(const Eigen::Vector3d& position, const Eigen::Vector3f& lo,
                    const Eigen::Vector3f& hi, const analysis_support::PrecisionFrame& frame,
                    const std::string& analysis) {
  const std::vector<Eigen::Vector3d> viewpoints{position};
  analysis_support::check_viewpoints(viewpoints, analysis);
  analysis_support::check_float_precision(lo, hi, viewpoints, frame, analysis);
}

constexpr const char* kCloudOrigin =
    "the origin of the cloud's local frame (its coordinates minus its global shift)";

}  // namespace

CloudStationView::CloudStationView(const PointCloud& cloud, std::optional<SurfelEstimate> surfels,
                                   const ScanOptions& options, const Progress& progress)
    : options_(options), surfels_(std::move(surfels)) {
  options_.surfels = surfels_ ? &*surfels_ : nullptr;
  options_.field_of_view.reset();
  cloud.validate();
  if (cloud.size() == 0) throw std::invalid_argument("station view: the cloud has no points");
  if (cloud.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("station view: more points than 32-bit indices hold");
  }
  analysis_support::check_point_model(cloud, {}, options_.point_radius, options_.surfels,
                                      "station view");
  cloud.bounds(lo_, hi_);
  radius_ = surfels_ ? surfels_->stats.radius_quantile_10 : options_.point_radius;
  indices_.resize(cloud.size());
  std::iota(indices_.begin(), indices_.end(), std::uint32_t{0});
  const auto start = Clock::now();
  progress("building octree", 0.0);
  tracer_ = std::make_unique<ScanTracer>(cloud, options_, progress);
  build_seconds_ = seconds_since(start);
}

CloudStationSight CloudStationView::see(const Eigen::Vector3d& position,
                                        const StationLimits& limits) const {
  check_position(position, lo_, hi_, {radius_, "point_radius", kCloudOrigin, "cloud"},
                 "station view");
  const StationLimitTest limit(limits);
  const auto start = Clock::now();
  CloudStationSight sight;
  sight.seen.assign(indices_.size(), 0);
  if (limit.unlimited()) {
    const std::size_t count = indices_.size();
    LargeVector<Ray> rays(count);
    LargeVector<std::uint8_t> blocked(count);
    tracer_->trace(position, indices_.data(), count, sight.seen.data(), rays.data(),
                   blocked.data());
  } else {
    // Only the points the limits admit are traced, as plan coverage does.
    std::vector<std::uint32_t> admitted;
    for (const std::uint32_t i : indices_) {
      if (limit.admits_point(position, tracer_->target(i))) admitted.push_back(i);
    }
    const std::size_t count = admitted.size();
    LargeVector<Ray> rays(count);
    LargeVector<std::uint8_t> blocked(count);
    LargeVector<std::uint8_t> seen(count);
    tracer_->trace(position, admitted.data(), count, seen.data(), rays.data(), blocked.data());
    for (std::size_t k = 0; k < count; ++k) sight.seen[admitted[k]] = seen[k];
  }
  for (const auto seen : sight.seen) sight.seen_points += seen;
  sight.trace_seconds = seconds_since(start);
  return sight;
}

MeshStationView::MeshStationView(const TriangleMesh& mesh, const MeshOcclusionOptions& options,
                                 const Progress& progress)
    : options_(options) {
  mesh.validate();
  if (mesh.faces.empty()) throw std::invalid_argument("station view: the mesh has no faces");
  analysis_support::check_positive(options.epsilon_scale, "epsilon_scale", "station view");
  mesh.bounds(lo_, hi_);
  if (!((hi_ - lo_).norm() > 0.0)) {
    throw std::invalid_argument("station view: the mesh's faces have no extent");
  }
  const auto start = Clock::now();
  progress("sampling", 0.0);
  samples_ = sample_mesh(mesh, options.samples_per_unit_area, options.seed, progress);
  areas_.resize(mesh.face_count());
  for (std::size_t f = 0; f < areas_.size(); ++f) areas_[f] = mesh.face_area(f);
  normals_ = face_unit_normals(mesh);
  // As compute_mesh_occlusion: traced around the mesh's centre, and nothing
  // farther than twice the diagonal can block a shadow ray.
  origin_ = 0.5 * (lo_ + hi_);
  reach_ = 2.0 * (hi_ - lo_).norm();
  epsilon_ = mesh_shadow_epsilon(mesh, options);
  progress("building octree", 0.0);
  tree_ = std::make_unique<TriangleOctree>(pack_triangles(mesh, origin_), options.octree, progress);
  build_seconds_ = seconds_since(start);
}

MeshStationSight MeshStationView::see(const Eigen::Vector3d& position,
                                      const StationLimits& limits) const {
  const Eigen::Vector3d local = position - origin_;
  check_position(local, (lo_ - origin_).cast<float>(), (hi_ - origin_).cast<float>(),
                 {(hi_ - lo_).norm(), "the mesh's diagonal", "the mesh's centre", "mesh"},
                 "station view");
  const StationLimitTest limit(limits);
  const auto start = Clock::now();
  const std::size_t count = samples_.size();
  LargeVector<Ray> rays(count);
  LargeVector<PrimitiveId> ignore(count);
  LargeVector<std::uint8_t> blocked(count);
  parallel_for(count, kRayGrain, options_.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) {
      if (!mesh_shadow_ray(samples_.points[s] - origin_, local, epsilon_, rays[s], reach_)) {
        rays[s] = analysis_support::unblockable_ray(local);
      }
      ignore[s] = samples_.face[s];
    }
  });
  tree_->occluded_batch(rays.data(), count, ignore.data(), blocked.data(), options_.threads);
  if (!limit.unlimited()) {
    // A sample outside the limits is not seen, as plan coverage counts it.
    for (std::size_t s = 0; s < count; ++s) {
      if (!limit.admits(samples_.points[s] - position, normals_[samples_.face[s]])) blocked[s] = 1;
    }
  }
  MeshStationSight sight;
  sight.face_seen_fraction.resize(areas_.size());
  for (std::size_t f = 0; f < areas_.size(); ++f) {
    std::size_t seen = 0;
    for (std::size_t s = samples_.first[f]; s < samples_.first[f + 1]; ++s) seen += !blocked[s];
    const double fraction = static_cast<double>(seen) / static_cast<double>(samples_.count_on(f));
    sight.face_seen_fraction[f] = static_cast<float>(fraction);
    sight.visible_area += fraction * areas_[f];
    sight.total_area += areas_[f];
  }
  sight.trace_seconds = seconds_since(start);
  return sight;
}

}  // namespace occlusion
