#include "occlusion/io/colour_ramp.hpp"

#include <algorithm>
#include <cmath>

namespace occlusion {
namespace {

// matplotlib's 256-entry viridis table at entries 0, 32, 64, ..., 224, 255 (about
// 0, 1/8, ..., 1). Linear interpolation between them stays within a few 8-bit
// levels of the full table.
constexpr double kViridis[9][3] = {
    {0.267004, 0.004874, 0.329415}, {0.278826, 0.175490, 0.483397}, {0.229739, 0.322361, 0.545706},
    {0.172719, 0.448791, 0.557885}, {0.127568, 0.566949, 0.550556}, {0.157851, 0.683765, 0.501686},
    {0.369214, 0.788888, 0.382914}, {0.678489, 0.863742, 0.189503}, {0.993248, 0.906157, 0.143936},
};
constexpr int kSegments = 8;

std::uint8_t to_byte(double unit) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
}

}  // namespace

std::array<std::uint8_t, 3> colour_ramp(double value) {
  if (std::isnan(value)) return {128, 128, 128};
  const double position = std::clamp(value, 0.0, 1.0) * kSegments;
  const int segment = std::min(static_cast<int>(position), kSegments - 1);
  const double fraction = position - segment;
  std::array<std::uint8_t, 3> rgb{};
  for (int channel = 0; channel < 3; ++channel) {
    const double from = kViridis[segment][channel];
    const double to = kViridis[segment + 1][channel];
    rgb[channel] = to_byte(from + fraction * (to - from));
  }
  return rgb;
}

}  // namespace occlusion
