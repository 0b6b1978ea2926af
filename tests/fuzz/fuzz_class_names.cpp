// class_names files: parsed from memory, as read_class_names_file does after reading the file.

#include "fuzz_support.hpp"
#include "occlusion/io/class_names_file.hpp"
#include "occlusion/io/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  fuzz::expect_only<InputError>(
      [&] { parse_class_names(fuzz::as_text(data, size), "fuzz.names"); });
  return 0;
}
