// load (a file of the data directory) and the upload that shares its reply.

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "command_params.hpp"
#include "command_table.hpp"
#include "loaded_scene.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "occlusion/io/named_paths.hpp"
#include "occlusion/io/obj_reader.hpp"
#include "occlusion/server/data_root.hpp"
#include "occlusion/server/protocol_error.hpp"
#include "upload.hpp"

namespace occlusion::server {

namespace fs = std::filesystem;

namespace {

std::string lower_case(std::string text) {
  for (auto& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// `display` is how errors name the file (the client's path, not ours).
// `max_memory_mb`: the server's budget, which bounds what a depth frame may
// decode to (CloudReadOptions::max_memory_mb).
std::shared_ptr<LoadedScene> read_scene(const fs::path& path, const std::string& display,
                                        bool skip_bad_lines, std::uint64_t max_memory_mb,
                                        const DataRoot& root) {
  try {
    if (lower_case(fs::path(path).extension().string()) == ".obj" && !fs::is_directory(path)) {
      auto mesh = std::make_shared<const TriangleMesh>(read_obj(path.string()));
      // Drawn in float32 as a cloud is: relative to the shift a cloud there
      // would get, so a mesh in UTM coordinates is not drawn to half a metre.
      auto scene =
          mesh_scene(*mesh, mesh->vertices.empty() ? Eigen::Vector3d::Zero()
                                                   : choose_global_shift(mesh->vertices.front()));
      scene->mesh = std::move(mesh);
      return scene;
    }
    CloudReadOptions options;
    options.skip_bad_lines = skip_bad_lines;
    options.max_memory_mb = max_memory_mb;
    CloudReadReport report;
    auto cloud = std::make_shared<const PointCloud>(read_cloud(path.string(), options, &report));
    auto scene = cloud_scene(*cloud);
    scene->cloud = std::move(cloud);
    scene->summary["dropped_nan"] = Json::UInt64(report.dropped_nan);
    scene->summary["skipped_lines"] = Json::UInt64(report.skipped_lines);
    // What reading found that the user should know (e.g. depths no indoor
    // sensor measures), as -poc and -fscan report it first: the viewer shows
    // it on load. A warning names the file as read; the client knows it by
    // `display` (an upload is read from its temporary name), as errors say,
    // and the files it names (a frame's image) relative to the data directory.
    Json::Value warnings(Json::arrayValue);
    for (const std::string& warning : report.warnings) {
      const bool named = warning.compare(0, path.string().size(), path.string()) == 0;
      warnings.append(
          root.relative_in(named ? display + warning.substr(path.string().size()) : warning));
    }
    scene->summary["warnings"] = warnings;
    return scene;
  } catch (const InputError& e) {
    if (e.path != path.string()) throw;
    throw InputError(display, e.line, e.reason);
  }
}

Json::Value reply(CommandContext& context, const LoadedScene& scene, const std::string& path,
                  bool cached) {
  context.progress()("sending", 1.0);
  context.send(scene.frames);
  Json::Value result = scene.summary;
  result["path"] = path;
  result["cached"] = cached;
  return result;
}

Json::Value load(CommandContext& context) {
  allow_keys(context.params, {"path", "skip_bad_lines"});
  const SceneLookup found = find_scene(context, required_string(context.params, "path"),
                                       bool_param(context.params, "skip_bad_lines", false));
  return reply(context, *found.scene, found.relative, found.cached);
}

}  // namespace

SceneLookup find_scene(CommandContext& context, const std::string& path, bool skip_bad_lines) {
  const DataRoot& root = context.server.root;
  const fs::path resolved = root.resolve(path, true);
  SceneLookup found;
  found.relative = root.relative(resolved.string());
  const std::string key = scene_key(resolved, skip_bad_lines ? "skip_bad_lines" : "");
  found.scene = context.server.cache.find(key);
  found.cached = found.scene != nullptr;
  if (!found.cached) {
    context.progress()("loading", 0.0);
    found.scene = read_scene(resolved, found.relative, skip_bad_lines,
                             context.server.limits.max_memory_mb, root);
    context.server.cache.insert(key, found.scene);
  }
  return found;
}

const std::vector<std::string>& upload_suffixes() {
  static const std::vector<std::string> suffixes = [] {
    std::vector<std::string> list = mesh_file_suffixes();
    for (const auto& suffix : cloud_file_suffixes()) {
      if (std::find(list.begin(), list.end(), suffix) == list.end()) list.push_back(suffix);
    }
    return list;
  }();
  return suffixes;
}

void check_upload_name(const std::string& name) {
  const auto fail = [&](const std::string& why) {
    throw ProtocolError("invalid_request", "upload name '" + name + "' " + why);
  };
  if (name.empty() || name.size() > 200) fail("must have 1 to 200 characters");
  if (name.find_first_of(std::string("/\\\0", 3)) != std::string::npos) {
    fail("must be a plain file name");
  }
  if (name[0] == '.') fail("must not start with '.'");
  if (!is_mesh_file(name) && !is_cloud_file(name)) {
    std::string list;
    for (const auto& suffix : upload_suffixes()) list += " " + suffix;
    fail("needs one of the endings" + list);
  }
}

Json::Value store_upload(CommandContext& context, const std::string& name, std::string_view bytes) {
  check_upload_name(name);
  const DataRoot& root = context.server.root;
  const fs::path folder = root.resolve("uploads", false);
  ensure_directory(folder.string());
  const fs::path target = root.resolve("uploads/" + name, false);
  // Hidden (list_files skips it) and with the upload's extension, which decides the reader.
  static std::atomic<unsigned long> counter{0};
  const fs::path temporary = folder / (".upload-" + std::to_string(static_cast<long>(::getpid())) +
                                       "-" + std::to_string(counter.fetch_add(1)) + "-" + name);
  struct Remove {
    const fs::path& path;
    bool keep = false;
    ~Remove() {
      std::error_code ignored;
      if (!keep) fs::remove(path, ignored);
    }
  } cleanup{temporary};
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw OutputError("uploads/" + name, "cannot store the upload");
  }
  context.progress()("reading", 0.0);
  const std::string relative = root.relative(target.string());
  // What the upload names is resolved, and refused, as the file it becomes:
  // the temporary lies in the same folder, but the client knows only that name.
  const NamedPathScope as_stored([&](const std::string& file, const std::string& named) {
    return root.resolve_named(file == temporary.string() ? target.string() : file, named).string();
  });
  const auto scene = read_scene(temporary, relative, false, context.server.limits.max_memory_mb,
                                context.server.root);
  context.progress().check_cancel();
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error) throw OutputError(relative, "cannot store the upload: " + error.message());
  cleanup.keep = true;
  return reply(context, *scene, relative, false);
}

std::vector<Command> load_commands() {
  return {Command{"load", Where::kWorker, &load, true}};
}

}  // namespace occlusion::server
