#pragma once
// Files sent by the browser: checked by reading them before they are stored,
// so a corrupt upload leaves nothing behind in the data directory.

#include <json/value.h>

#include <string>
#include <string_view>
#include <vector>

#include "command_context.hpp"

namespace occlusion::server {

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
