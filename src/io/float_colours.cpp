#include <algorithm>
#include <cmath>

#include "cloud_formats.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::detail {

std::vector<std::array<std::uint8_t, 3>> colours_from_floats(const std::vector<float>& rgb,
                                                             const std::string& path) {
  bool above_one = false;
  bool fraction = false;
  for (const float value : rgb) {
    above_one = above_one || value > 1.0f;
    fraction = fraction || (value > 0.0f && value < 1.0f);
  }
  const bool any_one = std::find(rgb.begin(), rgb.end(), 1.0f) != rgb.end();
  if (!above_one && !fraction && any_one) {
    throw InputError(path, 0,
                     "the floating-point colours are all 0 or 1, which fits both 0..1 and "
                     "0..255: store them as integers (uchar 0..255) or as 0..1 with their "
                     "fractions");
  }
  const float scale = above_one ? 1.0f : 255.0f;
  std::vector<std::array<std::uint8_t, 3>> colours(rgb.size() / 3);
  for (std::size_t i = 0; i < colours.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float value = std::min(255.0f, std::round(rgb[3 * i + c] * scale));
      colours[i][c] = static_cast<std::uint8_t>(value);
    }
  }
  return colours;
}

}  // namespace occlusion::detail
