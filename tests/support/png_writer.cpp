#include "support/png_writer.hpp"

#include "occlusion/io/png_writer.hpp"

#include <png.h>

#include <stdexcept>

namespace occlusion::testing {
namespace {

// libpng's simplified API: no longjmp to handle here.
void write_png(const std::string& path, std::size_t width, std::size_t height, png_uint_32 format,
               const void* pixels) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = format;
  if (png_image_write_to_file(&image, path.c_str(), 0, pixels, 0, nullptr) == 0) {
    throw std::runtime_error("cannot write " + path + ": " + image.message);
  }
}

}  // namespace

void write_depth_png(const std::string& path, std::size_t width, std::size_t height,
                     const std::vector<std::uint16_t>& values) {
  occlusion::write_depth_png(path, width, height, values);
}

void write_8bit_png(const std::string& path, std::size_t width, std::size_t height, int channels,
                    const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() != width * height * static_cast<std::size_t>(channels)) {
    throw std::invalid_argument("write_8bit_png: size");
  }
  const png_uint_32 format = channels == 1   ? PNG_FORMAT_GRAY
                             : channels == 3 ? PNG_FORMAT_RGB
                                             : PNG_FORMAT_RGBA;
  write_png(path, width, height, format, bytes.data());
}

}  // namespace occlusion::testing
