// E57 files. The page checksums are recomputed over the mutated bytes first:
// otherwise nearly every input would stop at the first checksum and the XML,
// the packets and the bit-packed fields behind it would go unfuzzed.
// (Checksum failures themselves are tested in tests/io/e57_reader_test.cpp.)

#include <string>

#include "fuzz_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "support/e57_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  std::string bytes(fuzz::as_text(data, size));
  test::fix_e57_checksums(bytes);
  const std::string path = fuzz::write_input(bytes, "fuzz.e57");
  fuzz::expect_only<InputError>([&] { read_cloud(path); });
  return 0;
}
