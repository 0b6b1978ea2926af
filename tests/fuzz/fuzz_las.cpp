// LAS files, every version and point format; LAZ must be refused, not read.

#include "fuzz_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  const std::string path = fuzz::write_input(fuzz::as_text(data, size), "fuzz.las");
  fuzz::expect_only<InputError>([&] { read_cloud(path); });
  return 0;
}
