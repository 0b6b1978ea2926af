#pragma once
// A request the server refuses, with the protocol's error code
// (docs/protocol.md, "Error codes"): sent back as {"type": "error", ...}.

#include <stdexcept>
#include <string>

namespace occlusion::server {

struct ProtocolError : std::runtime_error {
  ProtocolError(std::string error_code, const std::string& message)
      : std::runtime_error(message), code(std::move(error_code)) {}

  std::string code;  // e.g. "path_outside_data"
};

}  // namespace occlusion::server
