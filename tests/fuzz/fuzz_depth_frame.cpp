// Depth frames: the first byte says what the rest is. Even, the frame
// descriptor (beside a valid 4 x 3 depth image and colour image); odd, the
// depth PNG (beside a valid descriptor); so the descriptor's parser and
// libpng's decoding behind the PNG reader are both fuzzed.

#include <vector>

#include "fuzz_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "support/png_writer.hpp"

namespace {

constexpr const char* kDescriptor =
    R"({"depth": "depth.png", "colour": "colour.png", "depth_scale": 1000,
 "intrinsics": {"fx": 3, "fy": 3, "cx": 1.5, "cy": 1}, "pose_tum": [1, 2, 3, 0, 0, 0, 1]})";

void write_valid_images(bool depth_too) {
  const std::string directory = occlusion::fuzz::scratch_directory().string();
  occlusion::testing::write_8bit_png(directory + "/colour.png", 4, 3, 3,
                                     std::vector<std::uint8_t>(36, 200));
  if (depth_too) {
    std::vector<std::uint16_t> depth(12, 1000);
    depth[5] = 0;
    occlusion::testing::write_depth_png(directory + "/depth.png", 4, 3, depth);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  if (size == 0) return 0;
  const std::string_view rest = fuzz::as_text(data + 1, size - 1);
  const bool fuzz_png = (data[0] & 1) != 0;
  write_valid_images(!fuzz_png);
  if (fuzz_png) fuzz::write_input(rest, "depth.png");
  const std::string path =
      fuzz::write_input(fuzz_png ? std::string_view(kDescriptor) : rest, "fuzz.frame.json");
  fuzz::expect_only<InputError>([&] { read_cloud(path); });
  return 0;
}
