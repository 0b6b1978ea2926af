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
// same target, in this process or another, never share a temporary file. The
// tag goes in front, hidden, so the name keeps its extension: writers that
// pick the format by extension (write_cloud) write the right one.
fs::path temporary_path_beside(const fs::path& target) {
  static std::atomic<unsigned long> counter{0};
  const std::string name = ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-" +
                           std::to_string(counter.fetch_add(1)) + "-" + target.filename().string();
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

OutputSet::~OutputSet() {
  if (committed_) return;
  for (const auto& [temporary, target] : files_) remove_quietly(temporary);
}

std::string OutputSet::add(const std::string& target) {
  if (fs::path(target).filename().empty()) throw OutputError(target, "not a file name");
  for (const auto& file : files_) {
    if (file.second == target) throw OutputError(target, "named twice in one output set");
  }
  files_.emplace_back(temporary_path_beside(target).string(), target);
  return files_.back().first;
}

void OutputSet::commit() {
  // Checked before the first rename, so that a missing file cannot leave half
  // the set renamed.
  for (const auto& [temporary, target] : files_) {
    std::error_code status;
    if (!fs::is_regular_file(temporary, status)) {
      throw OutputError(target, "was not written, so no output of this run was kept");
    }
    if (fs::is_directory(target, status)) {
      throw OutputError(target, "is a directory, so no output of this run was kept");
    }
  }
  for (const auto& [temporary, target] : files_) {
    std::error_code status;
    fs::rename(temporary, target, status);
    if (status) throw OutputError(target, "cannot replace the file: " + status.message());
  }
  committed_ = true;
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
