#include "occlusion/io/atomic_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "occlusion/io/input_error.hpp"
#include "occlusion/io/output_recovery.hpp"

namespace occlusion {
namespace fs = std::filesystem;
namespace {

// Numbers temporaries and manifests apart within this process.
unsigned long next_serial() {
  static std::atomic<unsigned long> counter{0};
  return counter.fetch_add(1);
}

// Unique per process (pid) and per call (counter), so concurrent writers of the
// same target, in this process or another, never share a temporary file. The
// tag goes in front, hidden, so the name keeps its extension: writers that
// pick the format by extension (write_cloud) write the right one. The pid also
// tells a sweep (io/output_recovery.hpp) whether its writer still runs.
fs::path temporary_path_beside(const fs::path& target) {
  const std::string name = ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-" +
                           std::to_string(next_serial()) + "-" + target.filename().string();
  return target.parent_path() / name;
}

// The folders of the set's targets, each once, in order.
std::vector<fs::path> folders_of(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<fs::path> folders;
  for (const auto& file : files) {
    const fs::path folder = fs::path(file.second).parent_path();
    if (std::find(folders.begin(), folders.end(), folder) == folders.end()) {
      folders.push_back(folder);
    }
  }
  return folders;
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
  if (files_.empty()) {
    committed_ = true;
    return;
  }
  // A set a killed process left half renamed is finished before this one
  // replaces any of its files, so the newer outputs win.
  const std::vector<fs::path> folders = folders_of(files_);
  for (const auto& folder : folders) recover_outputs(folder.string());
  // One rename is atomic by itself; several are announced by a manifest that
  // a sweep finishes from, should this process die between them.
  std::string manifest;
  if (files_.size() > 1) {
    manifest = commit_manifest_path(folders.front().string(), static_cast<long>(::getpid()),
                                    next_serial());
    write_commit_manifest(manifest, files_);
  }
  for (const auto& [temporary, target] : files_) {
    std::error_code status;
    fs::rename(temporary, target, status);
    if (status) {
      // This process lives on and removes the rest: nothing for a sweep to finish.
      if (!manifest.empty()) remove_quietly(manifest);
      throw OutputError(target, "cannot replace the file: " + status.message());
    }
  }
  committed_ = true;
  if (!manifest.empty()) remove_quietly(manifest);
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
