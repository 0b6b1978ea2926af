#include "occlusion/analysis/mesh_occlusion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "analysis_support.hpp"
#include "occlusion/analysis/inside_solid.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/core/morton_order.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;

// Rays are traced in blocks so that progress and cancellation are checked
// between blocks while each block still keeps every core busy.
constexpr std::size_t kRaysPerBlock = std::size_t{1} << 16;
// Rays made per task: enough to outweigh handing out the task.
constexpr std::size_t kMadeRaysGrain = 4096;

// From a viewpoint at distance d, shadow rays meet the faces that lie along
// them at angles of about the mesh's size over d, while float places those
// faces to the mesh's size x 2^-23: whether such a ray hits is rounding within
// d x 2^-23 of the faces' edges. Up to the samples' spacing that moves the
// level by about one sample along each such edge, as sampling itself does;
// beyond, by more (a 5 x 5 x 3 box seen from x = 1e7 at 100 samples per unit
// area answered 0.8315 where it answers 0.8636 from x = 10).
void check_grazing_band(const std::vector<Eigen::Vector3d>& local_viewpoints, double density) {
  constexpr double kFloatSpacing = 1.0 / (1 << 23);
  const double spacing = 1.0 / std::sqrt(density);
  const double limit = spacing / kFloatSpacing;
  for (const auto& viewpoint : local_viewpoints) {
    const double distance = viewpoint.norm();
    if (!(distance > limit)) continue;
    throw std::invalid_argument(
        "mesh occlusion: a viewpoint lies " + std::to_string(distance) +
        " units from the mesh's centre; from there, rays that graze the faces lying along them "
        "hit or miss by rounding within " +
        std::to_string(distance * kFloatSpacing) +
        " units of those faces' edges, more than the samples are apart (" +
        std::to_string(spacing) + " units at samples_per_unit_area " + std::to_string(density) +
        "), which would move the level by more than sampling resolves: place viewpoints within " +
        std::to_string(limit) + " units of the mesh's centre, or lower samples_per_unit_area");
  }
}

void check_inputs(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& viewpoints,
                  const MeshOcclusionOptions& options) {
  mesh.validate();
  if (mesh.faces.empty()) throw std::invalid_argument("mesh occlusion: the mesh has no faces");
  analysis_support::check_viewpoints(viewpoints, "mesh occlusion");
  analysis_support::check_positive(options.epsilon_scale, "epsilon_scale", "mesh occlusion");
  // Viewpoints as far as float can trace from, by the cloud analyses' rule,
  // in the frame the rays are traced in (around the mesh's centre).
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0.0)) return;  // only degenerate faces: refused once their area is summed
  std::vector<Eigen::Vector3d> local_viewpoints;
  for (const auto& viewpoint : viewpoints) local_viewpoints.push_back(viewpoint - centre);
  analysis_support::check_float_precision(
      (lo - centre).cast<float>(), (hi - centre).cast<float>(), local_viewpoints,
      {diagonal, "the mesh's diagonal", "the mesh's centre", "mesh"}, "mesh occlusion");
  check_grazing_band(local_viewpoints, options.samples_per_unit_area);
}

}  // namespace

double mesh_shadow_epsilon(const TriangleMesh& mesh, const MeshOcclusionOptions& options) {
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  return options.epsilon_scale * std::max((hi - lo).norm(), 1e-30);
}

bool mesh_shadow_ray(const Eigen::Vector3d& sample, const Eigen::Vector3d& viewpoint,
                     double epsilon, Ray& ray, double reach) {
  const double length = (viewpoint - sample).norm();
  if (length <= 2.0 * epsilon) return false;
  if (length > reach) {
    // Nothing lies beyond `reach`: the same segment from the sample, cut
    // there, keeps float's precision (a viewpoint at 1e20 made the ray tests
    // overflow and see through walls), and no tolerance is needed at its far end.
    ray.origin = sample.cast<float>();
    ray.direction = ((viewpoint - sample) * (reach / length)).cast<float>();
    ray.t_min = static_cast<float>(epsilon / reach);
    ray.t_max = 1.0f;
    return true;
  }
  ray.origin = viewpoint.cast<float>();
  ray.direction = (sample - viewpoint).cast<float>();
  ray.t_min = static_cast<float>(epsilon / length);
  ray.t_max = static_cast<float>(1.0 - epsilon / length);
  return true;
}

std::vector<std::uint32_t> mesh_sample_order(const MeshSamples& samples, std::size_t first,
                                             std::size_t count, unsigned threads) {
  std::vector<Eigen::Vector3f> positions(count);
  for (std::size_t k = 0; k < count; ++k) positions[k] = samples.points[first + k].cast<float>();
  return morton_order(positions, threads);
}

MeshOcclusionResult compute_mesh_occlusion(const TriangleMesh& mesh,
                                           const std::vector<Eigen::Vector3d>& viewpoints,
                                           const MeshOcclusionOptions& options,
                                           const Progress& progress) {
  check_inputs(mesh, viewpoints, options);
  MeshOcclusionResult result;

  auto start = Clock::now();
  progress("sampling", 0.0);
  const MeshSamples samples =
      sample_mesh(mesh, options.samples_per_unit_area, options.seed, progress);
  result.timings.sampling_seconds = seconds_since(start);
  progress.check_cancel();

  // Rays are traced in a local frame around the mesh's centre: float keeps
  // seven digits, so a scene 5e6 units from the origin (a UTM northing) would
  // otherwise lose everything below half a unit. Samples and viewpoints stay
  // in double until they are relative to it.
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  const Eigen::Vector3d origin = 0.5 * (lo + hi);
  // Every sample lies within one diagonal of every face, so nothing that can
  // block a shadow ray is farther away than that.
  const double reach = 2.0 * std::max((hi - lo).norm(), 1e-30);
  std::vector<Eigen::Vector3d> local_viewpoints;
  for (const auto& viewpoint : viewpoints) local_viewpoints.push_back(viewpoint - origin);

  start = Clock::now();
  progress("building octree", 0.0);
  const TriangleOctree tree(pack_triangles(mesh, origin), options.octree, progress);
  result.timings.build_seconds = seconds_since(start);
  result.octree = tree.stats();
  progress.check_cancel();
  const std::vector<double> back_face_share = back_face_shares(tree, local_viewpoints);

  const double epsilon = mesh_shadow_epsilon(mesh, options);

  start = Clock::now();
  const std::size_t view_count = viewpoints.size();
  const std::size_t ray_count = samples.size() * view_count;
  // seen[s * view_count + v]: sample s is visible from viewpoint v.
  std::vector<std::uint8_t> seen(ray_count, 0);
  // Every (viewpoint, sample) pair of a block gets its slot, viewpoint-major
  // so that a viewpoint's rays trace together as packets, and the rays are
  // made on all threads: made one by one they took as long as tracing them.
  // A pair too close to need a ray gets one with an empty interval, which
  // nothing blocks, so the sample counts as seen from there. A block's samples
  // go in Morton order (mesh_sample_order), which keeps its memory to the block.
  const std::size_t samples_per_block = std::max<std::size_t>(1, kRaysPerBlock / view_count);
  LargeVector<Ray> rays(std::min(samples.size(), samples_per_block) * view_count);
  LargeVector<PrimitiveId> ignore(rays.size());
  LargeVector<std::uint8_t> blocked(rays.size());
  progress("tracing", 0.0);
  for (std::size_t first = 0; first < samples.size(); first += samples_per_block) {
    const std::size_t count = std::min(samples.size(), first + samples_per_block) - first;
    const std::vector<std::uint32_t> order =
        mesh_sample_order(samples, first, count, options.threads);
    parallel_for(count * view_count, kMadeRaysGrain, options.threads,
                 [&](std::size_t begin, std::size_t end) {
                   for (std::size_t i = begin; i < end; ++i) {
                     const std::size_t v = i / count, s = first + order[i % count];
                     if (!mesh_shadow_ray(samples.points[s] - origin, local_viewpoints[v], epsilon,
                                          rays[i], reach)) {
                       rays[i] = analysis_support::unblockable_ray(local_viewpoints[v]);
                     }
                     ignore[i] = samples.face[s];
                   }
                 });
    tree.occluded_batch(rays.data(), count * view_count, ignore.data(), blocked.data(),
                        options.threads, BatchOrder::kAsGiven);
    for (std::size_t v = 0; v < view_count; ++v) {
      for (std::size_t k = 0; k < count; ++k) {
        seen[(first + order[k]) * view_count + v] = blocked[v * count + k] ? 0 : 1;
      }
    }
    progress.check_cancel();
    progress("tracing", static_cast<double>(first + count) / static_cast<double>(samples.size()));
  }
  result.timings.trace_seconds = seconds_since(start);

  // Aggregate per face, per viewpoint and per group.
  result.faces = mesh.face_count();
  result.samples = samples.size();
  result.rays = ray_count;
  result.face_visible_fraction.resize(mesh.face_count());
  std::vector<double> viewpoint_area(view_count, 0.0);
  std::vector<std::size_t> seen_by_viewpoint(view_count);
  result.groups.resize(mesh.group_names.size());
  for (std::size_t g = 0; g < mesh.group_names.size(); ++g) {
    result.groups[g].name = mesh.group_names[g];
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    std::size_t visible = 0;
    std::fill(seen_by_viewpoint.begin(), seen_by_viewpoint.end(), 0);
    for (std::size_t s = samples.first[f]; s < samples.first[f + 1]; ++s) {
      bool any = false;
      for (std::size_t v = 0; v < view_count; ++v) {
        const bool from_v = seen[s * view_count + v] != 0;
        seen_by_viewpoint[v] += from_v ? 1 : 0;
        any = any || from_v;
      }
      visible += any ? 1 : 0;
    }
    const double count = static_cast<double>(samples.count_on(f));
    const double area = mesh.face_area(f);
    const double weight = static_cast<double>(visible) / count;
    result.face_visible_fraction[f] = static_cast<float>(weight);
    result.total_area += area;
    result.visible_area += weight * area;
    for (std::size_t v = 0; v < view_count; ++v) {
      viewpoint_area[v] += static_cast<double>(seen_by_viewpoint[v]) / count * area;
    }
    GroupVisibility& group = result.groups[mesh.face_group[f]];
    ++group.faces;
    group.total_area += area;
    group.visible_area += weight * area;
  }
  // Zero total area cannot happen for a validated mesh read from disk, but a
  // mesh built in code may hold only degenerate faces.
  if (!(result.total_area > 0.0)) {
    throw std::invalid_argument("mesh occlusion: the mesh has zero total area");
  }
  result.occlusion_level = 1.0 - result.visible_area / result.total_area;
  for (auto& group : result.groups) {
    group.occlusion_level =
        group.total_area > 0.0 ? 1.0 - group.visible_area / group.total_area : 0.0;
  }
  for (std::size_t v = 0; v < view_count; ++v) {
    result.viewpoints.push_back({viewpoints[v], viewpoint_area[v],
                                 viewpoint_area[v] / result.total_area, back_face_share[v]});
  }
  progress("done", 1.0);
  return result;
}

}  // namespace occlusion
