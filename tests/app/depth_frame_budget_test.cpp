// A depth PNG decodes to far more points than its bytes (deflate packs a
// constant image about 1000-fold: 39 KB held 16.7 million points in issue
// 44). The jobs' max_memory_mb bounds it from the image's header, before it
// is decoded, rather than their own estimate refusing it once it is.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "io/scratch_directory.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/io/input_error.hpp"
#include "support/png_writer.hpp"

namespace occlusion {
namespace {

// A flat wall 1.5 m away, 2048 x 2048 pixels: 4.2 million points from a
// file of a few kilobytes.
std::string flat_frame(const testing::ScratchDirectory& dir) {
  constexpr std::size_t kSide = 2048;
  testing::write_depth_png(dir.file("flat.png"), kSide, kSide,
                           std::vector<std::uint16_t>(kSide * kSide, 1500));
  const std::string path = dir.file("flat.frame.json");
  std::ofstream(path) << R"({"depth": "flat.png", "depth_scale": 1000,
      "intrinsics": {"fx": 1000, "fy": 1000, "cx": 1023.5, "cy": 1023.5}})";
  return path;
}

TEST(DepthFrameBudget, AJobRefusesAFrameFromItsHeaderBeforeDecodingIt) {
  const testing::ScratchDirectory dir;
  ScanRequest request;
  request.path = flat_frame(dir);
  ASSERT_LT(std::filesystem::file_size(dir.file("flat.png")), 64u * 1024);
  request.max_memory_mb = 16;
  std::string type, message;
  try {
    run_scan(request);
  } catch (const std::exception& e) {
    type = dynamic_cast<const InputError*>(&e) != nullptr ? "InputError" : typeid(e).name();
    message = e.what();
  }
  // Decoded first, the job's own estimate refused it as a UsageError.
  EXPECT_EQ(type, "InputError") << message;
  EXPECT_NE(message.find("flat.png is 2048 x 2048 pixels"), std::string::npos) << message;
  EXPECT_NE(message.find("more than max_memory_mb = 16 (refused before decoding it)"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace occlusion
