#pragma once
// Scenes read from the data directory (load, the live station) and files sent
// by the browser: checked by reading them before they are stored, so a
// corrupt upload leaves nothing behind in the data directory.

#include <json/value.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "command_context.hpp"
#include "loaded_scene.hpp"

namespace occlusion::server {

// A data file's scene: from the cache (SceneCache: the same file, unchanged,
// read with the same options), else read and cached.
struct SceneLookup {
  std::shared_ptr<const LoadedScene> scene;
  std::string relative;  // the path as the client names it
  bool cached = false;
};
SceneLookup find_scene(CommandContext& context, const std::string& path, bool skip_bad_lines);

// The file name endings `load` and uploads take: every mesh and cloud reader's
// (io), sent in hello so the viewer offers exactly these.
const std::vector<std::string>& upload_suffixes();

// Throws ProtocolError "invalid_request" unless `name` is a plain file name
// (no '/', not hidden) with an ending `load` reads.
void check_upload_name(const std::string& name);

// Reads `bytes` as the file `name`, stores it as DATA/uploads/<name> and
// streams it like `load`. InputError (naming uploads/<name>) when it does not read.
Json::Value store_upload(CommandContext& context, const std::string& name, std::string_view bytes);

}  // namespace occlusion::server
