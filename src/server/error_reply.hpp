#pragma once
// Which error code a failure is (docs/protocol.md, "Error codes"). Every
// exception a command can throw lands here, so none reaches the network loop.

#include <exception>
#include <string>

namespace occlusion::server {

struct ErrorReply {
  std::string code;
  std::string message;
};

ErrorReply classify(std::exception_ptr error);

}  // namespace occlusion::server
