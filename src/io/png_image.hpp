#pragma once
// PNG images for depth frames, decoded with libpng: a 16-bit single-channel
// depth image, and an 8-bit RGB colour image.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace occlusion::detail {

struct DepthImage {
  std::size_t width = 0, height = 0;
  std::vector<std::uint16_t> values;  // row by row, as the file stores them
};

struct ColourImage {
  std::size_t width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes a pixel, row by row
};

// Called with an image's width and height once its header is read, before
// anything is allocated for its pixels; it throws to refuse the image.
using PngSizeCheck = std::function<void(std::size_t width, std::size_t height)>;

// InputError naming the file for anything but a 16-bit greyscale PNG (an
// 8-bit or colour image holds no depth units), and for a corrupt one.
DepthImage read_depth_png(const std::string& path, const PngSizeCheck& check_size);
// Any PNG colour type (palette, grey, with alpha, 16-bit) as 8-bit RGB: alpha
// is dropped, 16-bit channels rounded to 8 bits. InputError if corrupt.
ColourImage read_colour_png(const std::string& path, const PngSizeCheck& check_size);

}  // namespace occlusion::detail
