#pragma once
// Files sent by the browser: checked by reading them before they are stored,
// so a corrupt upload leaves nothing behind in the data directory.

#include <json/value.h>

#include <string>
#include <string_view>

#include "command_context.hpp"

namespace occlusion::server {

// Throws ProtocolError "invalid_request" unless `name` is a plain file name
// (no '/', not hidden) with an extension `load` reads.
void check_upload_name(const std::string& name);

// Reads `bytes` as the file `name`, stores it as DATA/uploads/<name> and
// streams it like `load`. InputError (naming uploads/<name>) when it does not read.
Json::Value store_upload(CommandContext& context, const std::string& name, std::string_view bytes);

}  // namespace occlusion::server
