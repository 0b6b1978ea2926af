#include "occlusion/analysis/banded_discs.hpp"

#include "occlusion/core/parallel.hpp"

namespace occlusion {

LargeVector<BandedSurfel> banded_discs(const SurfelEstimate& estimate, unsigned threads) {
  constexpr std::size_t kGrain = 2048;
  LargeVector<BandedSurfel> discs(estimate.surfels.size());
  parallel_for(discs.size(), kGrain, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      const float sigma = estimate.noise.sigma.empty() ? 0.0f : estimate.noise.sigma[i];
      discs[i] = {estimate.surfels[i], kBandSigmas * sigma};
    }
  });
  return discs;
}

}  // namespace occlusion
