#pragma once
// The colour scale for per-element values in [0, 1] (visible fraction: 0 = fully
// occluded). Viridis: perceptually uniform, luminance rises monotonically, and
// it stays readable for colour-blind viewers and in greyscale print.

#include <array>
#include <cstdint>

namespace occlusion {

// 8-bit sRGB. Values are clamped to [0, 1]; NaN (no data) is mid grey, which is
// not on the ramp, so it cannot be mistaken for a measurement.
std::array<std::uint8_t, 3> colour_ramp(double value);

}  // namespace occlusion
