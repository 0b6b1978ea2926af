#include "occlusion/analysis/surface_closure.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "occlusion/core/random.hpp"
#include "occlusion/core/sampling.hpp"

namespace occlusion {

namespace {

// Directions within 60 degrees of the normal: |cos| >= 1/2.
constexpr double kMinCosine = 0.5;

}  // namespace

ClosureRays closure_rays(const SurfelEstimate& estimate, std::uint64_t seed, std::size_t samples) {
  ClosureRays closure;
  const LargeVector<Surfel>& surfels = estimate.surfels;
  const std::size_t oriented = estimate.stats.oriented;
  if (oriented == 0 || samples == 0) return closure;
  const std::size_t stride = std::max<std::size_t>(1, oriented / samples);
  std::size_t seen = 0;
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    const Surfel& s = surfels[i];
    if (!s.oriented() || seen++ % stride != 0) continue;
    Rng rng(seed, i);
    Eigen::Vector3d d;
    do {
      d = sample_sphere_direction(rng.uniform(), rng.uniform());
    } while (std::abs(d.dot(s.normal.cast<double>())) < kMinCosine);
    const Eigen::Vector3d step = 0.5 * static_cast<double>(s.radius) * d;
    closure.rays.push_back(Ray{(s.center.cast<double>() - step).cast<float>(),
                               (2.0 * step).cast<float>(), 0.0f, 1.0f});
    closure.own.push_back(static_cast<PrimitiveId>(i));
  }
  return closure;
}

double open_surface_share(const SurfelOctree& tree, const ClosureRays& closure, unsigned threads) {
  const std::size_t count = closure.rays.size();
  if (count == 0) return 0.0;
  std::vector<std::uint8_t> blocked(count);
  tree.occluded_batch(closure.rays.data(), count, closure.own.data(), blocked.data(), threads);
  const auto open = static_cast<std::size_t>(std::count(blocked.begin(), blocked.end(), 0));
  return static_cast<double>(open) / static_cast<double>(count);
}

}  // namespace occlusion
