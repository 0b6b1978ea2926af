#include "occlusion/analysis/mesh_sampling.hpp"

#include <cmath>
#include <stdexcept>

#include "occlusion/core/random.hpp"
#include "occlusion/core/sampling.hpp"

namespace occlusion {

std::size_t samples_for_area(double area, double samples_per_unit_area) {
  const double wanted = std::round(area * samples_per_unit_area);
  return wanted < 1.0 ? 1 : static_cast<std::size_t>(wanted);
}

namespace {

// Samples between two cancel checks: a few milliseconds of work.
constexpr std::size_t kSamplesPerBlock = std::size_t{1} << 16;

}  // namespace

MeshSamples sample_mesh(const TriangleMesh& mesh, double samples_per_unit_area, std::uint64_t seed,
                        const Progress& progress) {
  if (!std::isfinite(samples_per_unit_area) || samples_per_unit_area <= 0.0) {
    throw std::invalid_argument("samples_per_unit_area must be a finite number > 0");
  }
  const std::size_t face_count = mesh.face_count();
  MeshSamples samples;
  samples.first.resize(face_count + 1);
  samples.first[0] = 0;
  for (std::size_t f = 0; f < face_count; ++f) {
    samples.first[f + 1] =
        samples.first[f] + samples_for_area(mesh.face_area(f), samples_per_unit_area);
  }
  const std::size_t total = samples.first[face_count];
  samples.points.resize(total);
  samples.face.resize(total);
  std::size_t next_check = kSamplesPerBlock;
  for (std::size_t f = 0; f < face_count; ++f) {
    if (samples.first[f] >= next_check) {
      progress.check_cancel();
      progress("sampling", static_cast<double>(samples.first[f]) / static_cast<double>(total));
      next_check = samples.first[f] + kSamplesPerBlock;
    }
    const auto& corners = mesh.faces[f];
    Rng rng(seed, f);
    for (std::size_t s = samples.first[f]; s < samples.first[f + 1]; ++s) {
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
