#include "occlusion/io/png_writer.hpp"

#include <png.h>

#include <stdexcept>

#include "occlusion/io/input_error.hpp"

namespace occlusion {

void write_depth_png(const std::string& path, std::size_t width, std::size_t height,
                     const std::vector<std::uint16_t>& values) {
  if (width == 0 || height == 0 || values.size() != width * height) {
    throw std::invalid_argument("write_depth_png: " + std::to_string(values.size()) +
                                " values for " + std::to_string(width) + " x " +
                                std::to_string(height) + " pixels");
  }
  // libpng's simplified API: no longjmp to handle here.
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_LINEAR_Y;
  if (png_image_write_to_file(&image, path.c_str(), 0, values.data(), 0, nullptr) == 0) {
    throw OutputError(path, std::string("cannot write the PNG: ") + image.message);
  }
}

}  // namespace occlusion
