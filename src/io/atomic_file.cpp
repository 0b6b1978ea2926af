#include "occlusion/io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "occlusion/io/input_error.hpp"

namespace occlusion {
namespace fs = std::filesystem;
namespace {

// Unique per process (pid) and per call (counter), so concurrent writers of the
// same target, in this process or another, never share a temporary file.
fs::path temporary_path_beside(const fs::path& target) {
  static std::atomic<unsigned long> counter{0};
  const std::string name = "." + target.filename().string() + ".tmp." +
                           std::to_string(static_cast<long>(::getpid())) + "." +
                           std::to_string(counter.fetch_add(1));
  return target.parent_path() / name;
}

void remove_quietly(const fs::path& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

}  // namespace

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  const fs::path target(path);
  if (target.filename().empty()) throw OutputError(path, "not a file name");
  const fs::path temporary = temporary_path_beside(target);

  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  if (!out) {
    throw OutputError(path, "cannot create temporary file " + temporary.string() +
                                " (does the directory exist and is it writable?)");
  }
  try {
    write(out);
  } catch (...) {
    out.close();
    remove_quietly(temporary);
    throw;
  }
  out.flush();
  const bool written = out.good();
  out.close();
  if (!written || out.fail()) {
    remove_quietly(temporary);
    throw OutputError(path, "writing failed (disk full?)");
  }

  std::error_code status;
  fs::rename(temporary, target, status);
  if (status) {
    remove_quietly(temporary);
    throw OutputError(path, "cannot replace the file: " + status.message());
  }
}

void ensure_directory(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code status;
  const fs::file_status existing = fs::status(dir, status);
  if (fs::exists(existing)) {
    if (!fs::is_directory(existing)) throw OutputError(dir, "exists and is not a directory");
    return;
  }
  fs::create_directories(dir, status);
  if (status) throw OutputError(dir, "cannot create directory: " + status.message());
}

}  // namespace occlusion
