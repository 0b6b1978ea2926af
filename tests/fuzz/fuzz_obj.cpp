// OBJ meshes: parsed from memory, as read_obj does after reading the file.

#include "fuzz_support.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/obj_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  fuzz::expect_only<InputError>([&] { parse_obj(fuzz::as_text(data, size), "fuzz.obj"); });
  return 0;
}
