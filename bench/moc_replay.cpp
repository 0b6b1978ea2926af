#include "moc_replay.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "occlusion/analysis/mesh_occlusion.hpp"

namespace occlusion::bench {

ShadowRays make_shadow_rays(const MeshSamples& samples,
                            const std::vector<Eigen::Vector3d>& viewpoints, double epsilon) {
  ShadowRays out;
  out.samples = samples.size();
  out.viewpoints = viewpoints.size();
  out.rays.reserve(out.samples * out.viewpoints);
  out.ignore.reserve(out.rays.capacity());
  out.slot.reserve(out.rays.capacity());
  // Viewpoint by viewpoint, the samples in Morton order, as
  // compute_mesh_occlusion casts them (it orders each block of samples so).
  const std::vector<std::uint32_t> order = mesh_sample_order(samples, 0, samples.size());
  for (std::size_t v = 0; v < out.viewpoints; ++v) {
    for (const std::size_t s : order) {
      Ray ray;
      if (!mesh_shadow_ray(samples.points[s], viewpoints[v], epsilon, ray)) continue;
      out.rays.push_back(ray);
      out.ignore.push_back(samples.face[s]);
      out.slot.push_back(s * out.viewpoints + v);
    }
  }
  return out;
}

double occlusion_level_from_flags(const TriangleMesh& mesh, const MeshSamples& samples,
                                  const ShadowRays& shadow, const std::uint8_t* occluded) {
  std::vector<std::uint8_t> seen(shadow.samples * shadow.viewpoints, 1);
  for (std::size_t i = 0; i < shadow.rays.size(); ++i) seen[shadow.slot[i]] = occluded[i] ? 0 : 1;
  return occlusion_level_of_faces(mesh,
                                  face_visible_fractions(mesh, samples, shadow.viewpoints, seen));
}

std::vector<double> face_visible_fractions(const TriangleMesh& mesh, const MeshSamples& samples,
                                           std::size_t viewpoints,
                                           const std::vector<std::uint8_t>& seen) {
  std::vector<double> fractions(mesh.face_count(), 0.0);
  const auto stride = static_cast<std::ptrdiff_t>(viewpoints);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (samples.count_on(f) == 0) continue;
    std::size_t visible_samples = 0;
    for (std::size_t s = samples.first[f]; s < samples.first[f + 1]; ++s) {
      const auto from = seen.begin() + static_cast<std::ptrdiff_t>(s) * stride;
      visible_samples += std::find(from, from + stride, 1) != from + stride ? 1 : 0;
    }
    fractions[f] = static_cast<double>(visible_samples) / static_cast<double>(samples.count_on(f));
  }
  return fractions;
}

double occlusion_level_of_faces(const TriangleMesh& mesh, const std::vector<double>& fractions) {
  double total = 0.0;
  double visible = 0.0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const double area = mesh.face_area(f);
    total += area;
    visible += area * fractions[f];
  }
  return total > 0.0 ? 1.0 - visible / total : 0.0;
}

double samples_per_unit_area_for(const TriangleMesh& mesh, std::size_t samples) {
  std::vector<double> areas(mesh.face_count());
  double total = 0.0;
  for (std::size_t f = 0; f < areas.size(); ++f) total += areas[f] = mesh.face_area(f);
  if (!(total > 0.0)) throw std::invalid_argument("samples_per_unit_area_for: mesh has no area");
  const auto count = [&](double density) {
    std::size_t n = 0;
    for (const double a : areas) n += samples_for_area(a, density);
    return n;
  };
  // Never below the plain ratio: with one sample per face at least, a much
  // smaller density could reach the count but would be a meaningless figure.
  // Above it, per-face rounding makes the count a non-decreasing step
  // function of the density, so bisection finds the first step that suffices.
  double lo = static_cast<double>(samples) / total;
  if (count(lo) >= samples) return lo;
  double hi = lo;
  while (count(hi) < samples) hi *= 1.25;
  while (hi - lo > 1e-9 * hi) {
    const double mid = (lo + hi) / 2.0;
    if (count(mid) >= samples) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  return hi;
}

}  // namespace occlusion::bench
