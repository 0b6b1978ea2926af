#pragma once
// PNG images for the depth-frame tests, written with libpng.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion::testing {

// A 16-bit greyscale PNG (a depth image), values row by row.
void write_depth_png(const std::string& path, std::size_t width, std::size_t height,
                     const std::vector<std::uint16_t>& values);
// An 8-bit PNG: `channels` 1 (grey), 3 (RGB) or 4 (RGBA), bytes row by row.
void write_8bit_png(const std::string& path, std::size_t width, std::size_t height, int channels,
                    const std::vector<std::uint8_t>& bytes);

}  // namespace occlusion::testing
