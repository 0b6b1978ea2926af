// Text clouds (x y z [r g b] [label]), strict and with bad lines skipped.

#include "fuzz_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  const std::string path = fuzz::write_input(fuzz::as_text(data, size), "fuzz.xyz");
  fuzz::expect_only<InputError>([&] { read_cloud(path); });
  CloudReadOptions lenient;
  lenient.skip_bad_lines = true;
  fuzz::expect_only<InputError>([&] { read_cloud(path, lenient); });
  return 0;
}
