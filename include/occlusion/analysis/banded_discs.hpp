#pragma once
// The discs -fscan traces: each surfel of an estimate with its band, the
// noise its surface can explain (kBandSigmas times the sigma measured for it,
// surface_noise.hpp; 0 for an estimate made without its noise).

#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/banded_surfel.hpp"
#include "occlusion/core/large_buffer.hpp"

namespace occlusion {

LargeVector<BandedSurfel> banded_discs(const SurfelEstimate& estimate, unsigned threads);

}  // namespace occlusion
