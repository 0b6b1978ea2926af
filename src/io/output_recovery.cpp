#include "occlusion/io/output_recovery.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>

#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {
namespace fs = std::filesystem;
namespace {

// The manifest: this line, then each pair's temporary and target, relative to
// the manifest's folder, each ended by NUL (the one byte no file name holds).
constexpr char kManifestFormat[] = "occlusion output set 1\n";

// The PID in `.tmp-PID-...` or `.commit-PID-...`; nullopt for other names.
std::optional<long> writer_pid(const std::string& name, const std::string& prefix) {
  if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  std::size_t at = prefix.size();
  long pid = 0;
  for (; at < name.size() && name[at] >= '0' && name[at] <= '9' && pid < (1L << 40); ++at) {
    pid = pid * 10 + (name[at] - '0');
  }
  if (at == prefix.size() || at == name.size() || name[at] != '-' || pid <= 0) return std::nullopt;
  return pid;
}

// This process, or one that runs (perhaps as another user), may still be writing.
bool running(long pid) {
  if (pid == static_cast<long>(::getpid())) return true;
  if (pid > static_cast<long>(INT32_MAX)) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

std::string relative_to(const fs::path& dir, const std::string& path) {
  std::error_code ignored;
  return fs::absolute(path, ignored).lexically_relative(fs::absolute(dir, ignored)).string();
}

std::vector<std::pair<fs::path, fs::path>> read_manifest(const fs::path& manifest) {
  std::ifstream in(manifest, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::pair<fs::path, fs::path>> files;
  if (text.compare(0, sizeof kManifestFormat - 1, kManifestFormat) != 0) return files;
  std::vector<std::string> names;
  for (std::size_t at = sizeof kManifestFormat - 1; at < text.size();) {
    const std::size_t end = text.find('\0', at);
    if (end == std::string::npos) return {};  // cut short: not this format's file
    names.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  if (names.size() % 2 != 0) return {};
  const fs::path dir = manifest.parent_path();
  for (std::size_t i = 0; i < names.size(); i += 2) {
    files.emplace_back(dir / names[i], dir / names[i + 1]);
  }
  return files;
}

// Renames what is left of the set onto its targets. A target written after
// the manifest (by a later run) is newer than this set: it stays.
void finish_renames(const fs::path& manifest) {
  std::error_code status;
  const auto written = fs::last_write_time(manifest, status);
  if (status) return;
  for (const auto& [temporary, target] : read_manifest(manifest)) {
    std::error_code error;
    if (!fs::is_regular_file(temporary, error)) continue;  // renamed already
    const auto target_time = fs::last_write_time(target, error);
    if (!error && target_time > written) {
      fs::remove(temporary, error);
      continue;
    }
    fs::rename(temporary, target, error);
  }
}

}  // namespace

std::string commit_manifest_path(const std::string& dir, long pid, unsigned long serial) {
  return (fs::path(dir) / (".commit-" + std::to_string(pid) + "-" + std::to_string(serial)))
      .string();
}

void write_commit_manifest(const std::string& manifest,
                           const std::vector<std::pair<std::string, std::string>>& files) {
  const fs::path parent = fs::path(manifest).parent_path();
  const fs::path dir = parent.empty() ? fs::path(".") : parent;
  write_file_atomically(manifest, [&](std::ostream& out) {
    out << kManifestFormat;
    for (const auto& [temporary, target] : files) {
      out << relative_to(dir, temporary) << '\0' << relative_to(dir, target) << '\0';
    }
  });
}

RecoveredOutputs recover_outputs(const std::string& dir) {
  RecoveredOutputs recovered;
  std::vector<fs::path> manifests, temporaries;
  std::error_code error;
  for (fs::directory_iterator it(dir.empty() ? "." : dir, error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (const auto pid = writer_pid(name, ".commit-"); pid && !running(*pid)) {
      manifests.push_back(it->path());
    } else if (const auto writer = writer_pid(name, ".tmp-"); writer && !running(*writer)) {
      temporaries.push_back(it->path());
    }
  }
  // The sets first: their temporaries are the new outputs, not litter.
  for (const auto& manifest : manifests) {
    finish_renames(manifest);
    std::error_code ignored;
    if (fs::remove(manifest, ignored)) ++recovered.completed_sets;
  }
  for (const auto& temporary : temporaries) {
    std::error_code ignored;
    if (fs::remove(temporary, ignored)) ++recovered.removed_temporaries;
  }
  return recovered;
}

}  // namespace occlusion
