// ScanNet scenes: the input is the mesh (<scene>_vh_clean_2.ply), a line "--",
// then its labels file (<scene>_vh_clean_2.labels.ply); the scene folder is
// read, so both PLYs and the check of one against the other are fuzzed.

#include <filesystem>
#include <string>

#include "fuzz_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  namespace fs = std::filesystem;
  const fs::path scene = fuzz::scratch_directory() / "scene0000_00";
  std::error_code ignored;
  fs::remove_all(scene, ignored);
  fs::create_directories(scene);
  const std::string_view input = fuzz::as_text(data, size);
  const std::size_t separator = input.find("\n--\n");
  fuzz::write_input(input.substr(0, separator), "scene0000_00/scene0000_00_vh_clean_2.ply");
  if (separator != std::string_view::npos) {
    fuzz::write_input(input.substr(separator + 4),
                      "scene0000_00/scene0000_00_vh_clean_2.labels.ply");
  }
  fuzz::expect_only<InputError>([&] { read_cloud(scene.string()); });
  return 0;
}
