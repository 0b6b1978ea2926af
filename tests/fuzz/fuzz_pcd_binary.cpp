// PCD clouds with DATA binary (fuzz_pcd.hpp).

#include "fuzz_pcd.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  occlusion::fuzz::read_pcd_as(data, size, "binary");
  return 0;
}
