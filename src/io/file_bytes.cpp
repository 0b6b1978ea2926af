#include "file_bytes.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "occlusion/io/input_error.hpp"

namespace occlusion::detail {

std::string read_file_bytes(const std::string& path) {
  std::error_code status;
  if (std::filesystem::is_directory(path, status)) {
    throw InputError(path, 0, "is a directory, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::string bytes;
  const auto size = std::filesystem::file_size(path, status);
  if (!status) bytes.reserve(static_cast<std::size_t>(size));
  // Chunked rather than one read of file_size bytes, so pipes work too.
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    bytes.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(path, 0, std::string("read failed: ") + std::strerror(errno));
  return bytes;
}

}  // namespace occlusion::detail
