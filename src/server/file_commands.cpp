// Commands on the data directory itself: ping, list_files, save_polygon. They
// are quick, so they run on the network thread.

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "command_params.hpp"
#include "command_table.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/polygon_file.hpp"
#include "occlusion/server/protocol_error.hpp"

namespace occlusion::server {

namespace fs = std::filesystem;

namespace {

// Enough for any real folder; a bigger listing is cut, and says so.
constexpr std::size_t kMaxEntries = 10000;

std::string lower_extension(const fs::path& path) {
  std::string extension = path.extension().string();
  for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

std::string file_kind(const fs::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".obj") return "mesh";
  // A .txt is a label or openings file as often as a text cloud.
  if (extension == ".txt") return "text";
  if (is_cloud_file(path.string())) return "cloud";
  if (extension == ".json") return "json";
  return "other";
}

bool is_s3dis_room(const fs::path& dir) {
  std::error_code error;
  return fs::is_directory(dir / "Annotations", error);
}

std::string directory_kind(const fs::path& dir) {
  if (is_s3dis_room(dir)) return "s3dis_room";
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    if (is_s3dis_room(it->path())) return "s3dis_area";
  }
  return "directory";
}

Json::Value entry_json(const fs::path& path, const std::string& relative) {
  Json::Value entry(Json::objectValue);
  entry["name"] = path.filename().string();
  entry["path"] = relative;
  struct stat info {};
  // stat follows symbolic links: an entry is what it leads to.
  if (::stat(path.c_str(), &info) != 0) {
    entry["type"] = "other";
    entry["kind"] = "other";
  } else if (S_ISDIR(info.st_mode)) {
    entry["type"] = "directory";
    entry["kind"] = directory_kind(path);
  } else {
    entry["type"] = S_ISREG(info.st_mode) ? "file" : "other";
    entry["kind"] = file_kind(path);
    entry["size"] = Json::UInt64(info.st_size);
    entry["mtime"] = Json::Int64(info.st_mtime);
  }
  return entry;
}

Json::Value list_files(CommandContext& context) {
  allow_keys(context.params, {"dir"});
  const std::string dir = string_param(context.params, "dir", "");
  // Not an input: a folder holding a link that leads out is listed, without it.
  const fs::path resolved = context.server.root.resolve(dir, false);
  std::error_code status;
  if (!fs::exists(resolved, status)) {
    throw ProtocolError("not_found", "'" + dir + "' does not exist in the data directory");
  }
  if (!fs::is_directory(resolved)) {
    throw ProtocolError("invalid_request", "'" + dir + "' is not a directory");
  }
  std::vector<fs::path> children;
  // A name that is not UTF-8 cannot travel in JSON and come back as the same
  // bytes, so such an entry could never be opened: it is counted, not listed.
  std::size_t not_utf8 = 0;
  std::error_code error;
  for (fs::directory_iterator it(resolved, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (valid_utf8(name) != name) {
      ++not_utf8;
      continue;
    }
    children.push_back(it->path());
  }
  if (error) {
    throw ProtocolError("input_error", "'" + dir + "' cannot be listed: " + error.message());
  }
  std::sort(children.begin(), children.end());

  const std::string base = context.server.root.relative(resolved.string());
  Json::Value directories(Json::arrayValue), files(Json::arrayValue);
  for (std::size_t i = 0; i < children.size() && i < kMaxEntries; ++i) {
    const std::string name = children[i].filename().string();
    const std::string relative = base.empty() ? name : base + "/" + name;
    // A symbolic link that leads out is not shown: it could not be opened anyway.
    try {
      context.server.root.resolve(relative, false);
    } catch (const ProtocolError&) {
      continue;
    }
    Json::Value entry = entry_json(children[i], relative);
    (entry["type"] == "directory" ? directories : files).append(entry);
  }
  Json::Value result(Json::objectValue);
  result["dir"] = base;
  result["entries"] = Json::Value(Json::arrayValue);
  for (const auto& group : {directories, files}) {
    for (const auto& entry : group) result["entries"].append(entry);
  }
  result["truncated"] = children.size() > kMaxEntries;
  result["not_utf8"] = Json::UInt64(not_utf8);
  return result;
}

std::vector<std::vector<Eigen::Vector3d>> read_polygon_param(const Json::Value& params) {
  if (!params.isMember("polygons")) {
    throw ProtocolError("invalid_request", "missing parameter 'polygons'");
  }
  const Json::Value& list = params["polygons"];
  const auto fail = [](const std::string& why) {
    throw ProtocolError("invalid_request", "'polygons' " + why);
  };
  if (!list.isArray() || list.empty()) fail("must be a non-empty list of polygons");
  std::vector<std::vector<Eigen::Vector3d>> polygons;
  for (Json::ArrayIndex p = 0; p < list.size(); ++p) {
    const std::string where = "polygon " + std::to_string(p + 1);
    if (!list[p].isArray() || list[p].size() < 3) fail(where + " needs at least 3 points");
    std::vector<Eigen::Vector3d> polygon;
    for (const auto& point : list[p]) {
      if (!point.isArray() || point.size() != 3) fail(where + ": a point is [x, y, z]");
      Eigen::Vector3d position;
      for (Json::ArrayIndex k = 0; k < 3; ++k) {
        if (!point[k].isNumeric() || point[k].isBool() || !std::isfinite(point[k].asDouble())) {
          fail(where + ": coordinates must be finite numbers");
        }
        position[static_cast<int>(k)] = point[k].asDouble();
      }
      polygon.push_back(position);
    }
    polygons.push_back(std::move(polygon));
  }
  return polygons;
}

// The first line write_polygons gives every openings file.
constexpr std::string_view kOpeningsHeader = "# openings";

bool starts_with_openings_header(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string first(kOpeningsHeader.size(), '\0');
  in.read(first.data(), static_cast<std::streamsize>(first.size()));
  return in && first == kOpeningsHeader;
}

// save_polygon writes openings files and nothing else: a ".txt" name, never
// in a scene folder (an S3DIS room reads every .txt in it), never the server's
// out/ or uploads/ folders themselves, and over an existing file only when it
// is an openings file (a text cloud is a .txt too).
void check_openings_target(const DataRoot& root, const std::string& path,
                           const fs::path& resolved) {
  const auto refuse = [&](const std::string& why) {
    throw ProtocolError("invalid_request", "'" + path + "' " + why);
  };
  if (resolved == root.path() || fs::is_directory(resolved)) refuse("is a directory");
  if (lower_extension(resolved) != ".txt") {
    refuse("is not an openings file name: save_polygon writes '.txt' files only");
  }
  const std::string relative = root.relative(resolved.string());
  for (const char* reserved : {"out", "uploads"}) {
    if (relative == reserved) refuse("is the server's own folder");
  }
  for (fs::path dir = resolved.parent_path(); dir != root.path() && dir.has_relative_path();
       dir = dir.parent_path()) {
    if (is_s3dis_room(dir) || dir.filename() == "Annotations") {
      refuse(
          "is inside a scene folder, whose .txt files are read as the scene; save it beside "
          "the scene instead");
    }
  }
  std::error_code status;
  if (fs::exists(fs::symlink_status(resolved, status))) {
    if (!fs::is_regular_file(resolved, status) || !starts_with_openings_header(resolved)) {
      refuse(
          "exists and is not an openings file (its first line is not '# openings'); choose "
          "another name");
    }
  }
}

Json::Value save_polygon(CommandContext& context) {
  allow_keys(context.params, {"path", "polygons", "append"});
  const std::string path = required_string(context.params, "path");
  const bool append = bool_param(context.params, "append", false);
  auto polygons = read_polygon_param(context.params);
  const fs::path resolved = context.server.root.resolve(path, false);
  check_openings_target(context.server.root, path, resolved);
  if (append && fs::exists(resolved)) {
    auto existing = read_polygons(resolved.string());
    existing.insert(existing.end(), polygons.begin(), polygons.end());
    polygons = std::move(existing);
  }
  ensure_directory(resolved.parent_path().string());
  write_polygons(resolved.string(), polygons);
  Json::Value result(Json::objectValue);
  result["path"] = context.server.root.relative(resolved.string());
  result["polygons"] = Json::UInt64(polygons.size());
  return result;
}

// The polygons of an openings file, so the viewer can draw the openings a
// computation uses and keep them when it saves more.
Json::Value read_polygon_file(CommandContext& context) {
  allow_keys(context.params, {"path"});
  const std::string path = required_string(context.params, "path");
  const fs::path resolved = context.server.root.resolve(path, true);
  Json::Value list(Json::arrayValue);
  for (const auto& polygon : read_polygons(resolved.string())) {
    Json::Value points(Json::arrayValue);
    for (const auto& p : polygon) {
      Json::Value point(Json::arrayValue);
      for (int k = 0; k < 3; ++k) point.append(p[k]);
      points.append(point);
    }
    list.append(points);
  }
  Json::Value result(Json::objectValue);
  result["path"] = context.server.root.relative(resolved.string());
  result["polygons"] = list;
  return result;
}

}  // namespace

std::vector<Command> file_commands() {
  return {
      Command{"ping", Where::kNetwork,
              [](CommandContext&) { return Json::Value(Json::objectValue); }},
      Command{"list_files", Where::kNetwork, &list_files},
      Command{"save_polygon", Where::kNetwork, &save_polygon},
      Command{"read_polygons", Where::kNetwork, &read_polygon_file},
  };
}

}  // namespace occlusion::server
