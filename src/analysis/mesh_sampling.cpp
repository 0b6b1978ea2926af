#include "occlusion/analysis/mesh_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "occlusion/core/random.hpp"
#include "occlusion/core/sampling.hpp"

namespace occlusion {

namespace {

constexpr std::size_t kCountLimit = std::numeric_limits<std::size_t>::max();

// a + b, saturating at kCountLimit.
std::size_t plus(std::size_t a, std::size_t b) {
  return a > kCountLimit - b ? kCountLimit : a + b;
}

}  // namespace

std::size_t samples_for_area(double area, double samples_per_unit_area) {
  const double wanted = std::round(area * samples_per_unit_area);
  if (wanted < 1.0) return 1;
  // 2^64 and beyond (and NaN) saturate: converted, they were undefined and
  // came out as 0 samples or a length error.
  if (!(wanted < 18446744073709551616.0)) return kCountLimit;
  return static_cast<std::size_t>(wanted);
}

namespace {

// Samples between two cancel checks: a few milliseconds of work.
constexpr std::size_t kSamplesPerBlock = std::size_t{1} << 16;

void check_density(double samples_per_unit_area) {
  if (!std::isfinite(samples_per_unit_area) || samples_per_unit_area <= 0.0) {
    throw std::invalid_argument("samples_per_unit_area must be a finite number > 0");
  }
}

}  // namespace

std::size_t total_samples(const TriangleMesh& mesh, double samples_per_unit_area) {
  std::size_t total = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    total = plus(total, samples_for_area(mesh.face_area(f), samples_per_unit_area));
  }
  return total;
}

double density_for_min_samples(const TriangleMesh& mesh, double samples_per_unit_area,
                               std::size_t min_samples) {
  check_density(samples_per_unit_area);
  if (total_samples(mesh, samples_per_unit_area) >= min_samples) return samples_per_unit_area;
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) area += mesh.face_area(f);
  if (!(area > 0.0)) return samples_per_unit_area;  // no area to sample more densely
  // Each face gets at least round(area_f * d) >= area_f * d - 1/2 samples, so
  // this density is enough; the count only grows with the density, so
  // bisection finds the smallest one.
  double lo = samples_per_unit_area;
  double hi = std::max(
      lo, (static_cast<double>(min_samples) + 0.5 * static_cast<double>(mesh.face_count()) + 1.0) /
              area);
  for (int step = 0; step < 200 && hi - lo > 1e-9 * hi; ++step) {
    const double mid = 0.5 * (lo + hi);
    (total_samples(mesh, mid) >= min_samples ? hi : lo) = mid;
  }
  return hi;
}

MeshSamples sample_mesh(const TriangleMesh& mesh, double samples_per_unit_area, std::uint64_t seed,
                        const Progress& progress) {
  check_density(samples_per_unit_area);
  const std::size_t face_count = mesh.face_count();
  MeshSamples samples;
  samples.first.resize(face_count + 1);
  samples.first[0] = 0;
  for (std::size_t f = 0; f < face_count; ++f) {
    samples.first[f + 1] =
        plus(samples.first[f], samples_for_area(mesh.face_area(f), samples_per_unit_area));
  }
  const std::size_t total = samples.first[face_count];
  if (total > samples.points.max_size()) {
    throw std::invalid_argument(
        "mesh sampling: samples_per_unit_area " + std::to_string(samples_per_unit_area) +
        " gives " + (total == kCountLimit ? "more than " : "") + std::to_string(total) +
        " samples on this mesh, more than can be held; lower samples_per_unit_area");
  }
  samples.points.resize(total);
  samples.face.resize(total);
  // Checked by sample count, not by face: one large face of a coarse mesh
  // can hold millions of samples.
  std::size_t next_check = kSamplesPerBlock;
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto& corners = mesh.faces[f];
    Rng rng(seed, f);
    for (std::size_t s = samples.first[f]; s < samples.first[f + 1]; ++s) {
      if (s >= next_check) {
        progress.check_cancel();
        progress("sampling", static_cast<double>(s) / static_cast<double>(total));
        next_check = s + kSamplesPerBlock;
      }
      const double r1 = rng.uniform();
      const double r2 = rng.uniform();
      samples.points[s] = sample_triangle(mesh.vertices[corners[0]], mesh.vertices[corners[1]],
                                          mesh.vertices[corners[2]], r1, r2);
      samples.face[s] = static_cast<std::uint32_t>(f);
    }
  }
  return samples;
}

}  // namespace occlusion
