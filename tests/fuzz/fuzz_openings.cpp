// Openings files (polygons of 3-D points, blank-line separated).

#include "fuzz_support.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/polygon_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  const std::string path = fuzz::write_input(fuzz::as_text(data, size), "openings.txt");
  fuzz::expect_only<InputError>([&] { read_polygons(path); });
  return 0;
}
