// Per-point label files, and the sniffer that tells them from text clouds.

#include "fuzz_support.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/label_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  const std::string path = fuzz::write_input(fuzz::as_text(data, size), "fuzz.txt");
  fuzz::expect_only<InputError>([&] { is_label_file(path); });
  fuzz::expect_only<InputError>([&] { read_label_file(path); });
  return 0;
}
