// PCD clouds with DATA binary_compressed (fuzz_pcd.hpp).

#include "fuzz_pcd.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  occlusion::fuzz::read_pcd_as(data, size, "binary_compressed");
  return 0;
}
