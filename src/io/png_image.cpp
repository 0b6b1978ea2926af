// libpng reports errors by longjmp. So the calls into libpng live in
// functions whose frames hold nothing with a destructor (setjmp's rules for
// C++), write into buffers the caller owns, and return false with libpng's
// message; the caller turns that into an InputError.

#include "png_image.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::detail {
namespace {

// The largest image side read: depth cameras give at most a few thousand.
constexpr png_uint_32 kMaxSide = 1u << 15;
// Deflate expands at most 1032-fold, so a file of n bytes decodes to at most
// ~1032 n bytes: a larger claim is a corrupt header, refused before allocating.
constexpr std::uint64_t kMaxDeflateRatio = 1032;

struct PngState {
  png_structp png = nullptr;
  png_infop info = nullptr;
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t at = 0;
  char message[256] = {};
};

struct PngLayout {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
};

void on_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void read_bytes(png_structp png, png_bytep out, png_size_t count) {
  auto* state = static_cast<PngState*>(png_get_io_ptr(png));
  if (count > state->size - state->at) png_error(png, "the file ends inside the image");
  std::memcpy(out, state->data + state->at, count);
  state->at += count;
}

bool read_layout(PngState& state, PngLayout& layout) {
  if (setjmp(png_jmpbuf(state.png))) return false;
  png_set_user_limits(state.png, kMaxSide, kMaxSide);
  png_set_read_fn(state.png, &state, read_bytes);
  png_read_info(state.png, state.info);
  layout.width = png_get_image_width(state.png, state.info);
  layout.height = png_get_image_height(state.png, state.info);
  layout.bit_depth = png_get_bit_depth(state.png, state.info);
  layout.colour_type = png_get_color_type(state.png, state.info);
  return true;
}

// Decodes into `rows` (one pointer per row, each row_bytes long) after the
// transformations that give 8-bit RGB (`to_rgb`) or leave the samples as
// they are; false if libpng fails or the rows would not be row_bytes.
bool read_rows(PngState& state, bool to_rgb, png_bytepp rows, png_size_t row_bytes) {
  if (setjmp(png_jmpbuf(state.png))) return false;
  if (to_rgb) {
    png_set_palette_to_rgb(state.png);
    png_set_expand_gray_1_2_4_to_8(state.png);
    png_set_gray_to_rgb(state.png);
    png_set_scale_16(state.png);
    png_set_strip_alpha(state.png);
  }
  png_set_interlace_handling(state.png);
  png_read_update_info(state.png, state.info);
  if (png_get_rowbytes(state.png, state.info) != row_bytes) {
    std::snprintf(state.message, sizeof state.message,
                  "rows of %zu bytes after decoding, not the %zu expected",
                  static_cast<std::size_t>(png_get_rowbytes(state.png, state.info)),
                  static_cast<std::size_t>(row_bytes));
    return false;
  }
  png_read_image(state.png, rows);
  png_read_end(state.png, nullptr);
  return true;
}

class PngReader {
 public:
  explicit PngReader(const std::string& path) : path_(path), bytes_(read_file_bytes(path)) {
    if (bytes_.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes_.data()), 0, 8)) {
      throw InputError(path_, 0, "not a PNG file (no PNG signature at byte 0)");
    }
    state_.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state_, on_error, on_warning);
    if (state_.png != nullptr) state_.info = png_create_info_struct(state_.png);
    if (state_.info == nullptr) throw std::bad_alloc();
    state_.data = reinterpret_cast<const unsigned char*>(bytes_.data());
    state_.size = bytes_.size();
    if (!read_layout(state_, layout_)) fail();
  }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;

  const PngLayout& layout() const { return layout_; }

  // Decodes into `pixels`, sized here once the size is known to be possible.
  void read(bool to_rgb, std::size_t row_bytes, std::vector<unsigned char>& pixels) {
    const std::uint64_t decoded = std::uint64_t{layout_.height} * (row_bytes + 1);
    if (decoded > kMaxDeflateRatio * bytes_.size()) {
      throw InputError(path_, 0,
                       "corrupt: a " + std::to_string(layout_.width) + " x " +
                           std::to_string(layout_.height) + " image of " + std::to_string(decoded) +
                           " bytes cannot be compressed into " + std::to_string(bytes_.size()) +
                           " bytes (deflate shrinks at most " + std::to_string(kMaxDeflateRatio) +
                           "-fold)");
    }
    pixels.resize(static_cast<std::size_t>(layout_.height) * row_bytes);
    std::vector<png_bytep> rows(layout_.height);
    for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = pixels.data() + r * row_bytes;
    if (!read_rows(state_, to_rgb, rows.data(), row_bytes)) fail();
  }

  [[noreturn]] void fail() const {
    throw InputError(path_, 0, std::string("not a valid PNG file: ") + state_.message);
  }

  const std::string& path() const { return path_; }

 private:
  // Frees libpng's structures also when the constructor throws (a member's
  // destructor runs then; the reader's own would not: fuzz_depth_frame found
  // that leak).
  struct PngFree {
    PngState& state;
    ~PngFree() { png_destroy_read_struct(&state.png, &state.info, nullptr); }
  };

  const std::string& path_;
  std::string bytes_;
  PngState state_;
  PngFree free_{state_};
  PngLayout layout_;
};

}  // namespace

DepthImage read_depth_png(const std::string& path, const PngSizeCheck& check_size) {
  PngReader reader(path);
  const PngLayout& layout = reader.layout();
  if (layout.colour_type != PNG_COLOR_TYPE_GRAY || layout.bit_depth != 16) {
    throw InputError(path, 0,
                     "a depth image must be a 16-bit single-channel (greyscale) PNG, as TUM, "
                     "Redwood, ScanNet and NYU store depth; this one has " +
                         std::to_string(layout.bit_depth) + "-bit samples and PNG colour type " +
                         std::to_string(layout.colour_type));
  }
  check_size(layout.width, layout.height);
  std::vector<unsigned char> pixels;
  reader.read(false, std::size_t{layout.width} * 2, pixels);
  DepthImage image;
  image.width = layout.width;
  image.height = layout.height;
  image.values.resize(image.width * image.height);
  // PNG stores 16-bit samples most significant byte first.
  for (std::size_t i = 0; i < image.values.size(); ++i) {
    image.values[i] = static_cast<std::uint16_t>((pixels[2 * i] << 8) | pixels[2 * i + 1]);
  }
  return image;
}

ColourImage read_colour_png(const std::string& path, const PngSizeCheck& check_size) {
  PngReader reader(path);
  check_size(reader.layout().width, reader.layout().height);
  ColourImage image;
  image.width = reader.layout().width;
  image.height = reader.layout().height;
  reader.read(true, image.width * 3, image.rgb);
  return image;
}

}  // namespace occlusion::detail
