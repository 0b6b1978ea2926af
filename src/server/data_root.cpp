#include "occlusion/server/data_root.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "occlusion/server/protocol_error.hpp"

namespace occlusion::server {

namespace fs = std::filesystem;

namespace {

bool inside(const fs::path& root, const fs::path& path) {
  const auto [root_end, path_end] =
      std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  (void)path_end;
  return root_end == root.end();
}

// A path whose links cannot be resolved: a loop of symbolic links (or one
// too long) is the data's fault, not the server's, and it is not outside.
ProtocolError unfollowable(const std::string& relative, const std::error_code& error) {
  const bool loop = error == std::errc::too_many_symbolic_link_levels;
  return ProtocolError("input_error", "'" + relative + "' cannot be followed: " + error.message() +
                                          (loop ? " (a loop of symbolic links)" : ""));
}

// Folders below an input folder that readers look into: Area/room/Annotations/file.
constexpr int kNestedDepth = 4;
// A folder with more entries than this is not walked to the end; it is refused.
constexpr std::size_t kMaxNestedEntries = 200000;

}  // namespace

DataRoot::DataRoot(const std::string& directory) {
  std::error_code error;
  root_ = fs::canonical(directory.empty() ? "." : directory, error);
  if (error || !fs::is_directory(root_)) {
    throw std::invalid_argument("data directory '" + directory + "' is not a directory");
  }
  prefix_ = root_.string();
  if (prefix_.back() != '/') prefix_ += '/';
}

fs::path DataRoot::resolve(const std::string& relative, bool must_exist) const {
  if (relative.find('\0') != std::string::npos) {
    throw ProtocolError("path_outside_data", "a path must not contain NUL characters");
  }
  const fs::path given(relative);
  if (given.is_absolute() || given.has_root_name()) {
    throw ProtocolError("path_outside_data",
                        "'" + relative + "' is absolute; paths are relative to the data directory");
  }
  // weakly_canonical resolves the symbolic links of the part that exists and
  // folds `..` in the rest, so the prefix test below sees where the path leads.
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(root_ / given, error);
  if (error) throw unfollowable(relative, error);
  if (!inside(root_, resolved)) {
    throw ProtocolError("path_outside_data", "'" + relative + "' is outside the data directory");
  }
  if (must_exist && !fs::exists(resolved, error)) {
    throw ProtocolError("not_found", "'" + relative + "' does not exist in the data directory");
  }
  // A folder read as a scene (an S3DIS room or Area) is read file by file: a
  // link inside it must not lead out either.
  if (must_exist && resolved != root_ && fs::is_directory(resolved, error)) {
    std::size_t seen = 0;
    check_nested(resolved, relative, kNestedDepth, seen);
  }
  return resolved;
}

fs::path DataRoot::resolve_named(const std::string& file, const std::string& named) const {
  // A file outside (it cannot be one) keeps its absolute folder: refused below.
  const fs::path folder = relative(fs::path(file).parent_path().string());
  const fs::path given(named);
  try {
    return resolve(given.is_absolute() ? named : (folder / given).string(), false);
  } catch (const ProtocolError& e) {
    throw ProtocolError(e.code, "'" + relative(file) + "' names '" + named + "': " + e.what());
  }
}

void DataRoot::check_nested(const fs::path& dir, const std::string& relative, int depth,
                            std::size_t& seen) const {
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    if (++seen > kMaxNestedEntries) {
      throw ProtocolError("invalid_request", "'" + relative + "' holds more than " +
                                                 std::to_string(kMaxNestedEntries) +
                                                 " entries; name a smaller folder");
    }
    const std::string name =
        (relative.empty() ? "" : relative + "/") + it->path().filename().string();
    std::error_code status;
    if (it->is_symlink(status)) {
      const fs::path target = fs::weakly_canonical(it->path(), status);
      if (status) throw unfollowable(name, status);
      if (!inside(root_, target)) {
        throw ProtocolError("path_outside_data",
                            "'" + name + "' is a link that leads outside the data directory");
      }
    }
    if (depth > 1 && it->is_directory(status)) check_nested(it->path(), name, depth - 1, seen);
  }
}

std::string DataRoot::relative(const std::string& path) const {
  if (path == root_.string()) return "";
  if (path.compare(0, prefix_.size(), prefix_) == 0) return path.substr(prefix_.size());
  return path;
}

std::string DataRoot::relative_in(const std::string& text) const {
  if (text == root_.string()) return "";
  std::string out;
  std::size_t from = 0;
  for (std::size_t at = text.find(prefix_); at != std::string::npos;
       at = text.find(prefix_, at + 1)) {
    // Only where a path starts: not within another path ("/x/data/..." of root "/data").
    if (at > 0 && std::string_view(" \t'\"([=").find(text[at - 1]) == std::string_view::npos) {
      continue;
    }
    out.append(text, from, at - from);
    from = at + prefix_.size();
    at = from - 1;
  }
  return from == 0 ? text : out + text.substr(from);
}

void DataRoot::relativise(Json::Value& json) const {
  if (json.isString()) {
    const std::string text = json.asString();
    const std::string shorter = relative_in(text);
    if (shorter != text) json = shorter;
  } else if (json.isArray() || json.isObject()) {
    for (auto& member : json) relativise(member);
  }
}

}  // namespace occlusion::server
