#pragma once
// The three PCD targets share this: the input is a whole file, header
// included, but its DATA line is set to the target's encoding, so each
// target always reaches its own body decoder (ascii parsing here, binary
// and LZF decoding in PCL) while the header is fuzzed too.

#include <string>

#include "fuzz_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::fuzz {

inline std::string with_data_line(std::string bytes, const std::string& encoding) {
  const std::size_t data = bytes.find("\nDATA ");
  if (data == std::string::npos) return bytes;
  const std::size_t start = data + 6;
  std::size_t end = bytes.find_first_of("\r\n", start);
  if (end == std::string::npos) end = bytes.size();
  return bytes.replace(start, end - start, encoding);
}

inline void read_pcd_as(const std::uint8_t* data, std::size_t size, const std::string& encoding) {
  const std::string bytes = with_data_line(std::string(as_text(data, size)), encoding);
  const std::string path = write_input(bytes, "fuzz.pcd");
  expect_only<InputError>([&] { read_cloud(path); });
}

}  // namespace occlusion::fuzz
