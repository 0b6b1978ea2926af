#pragma once
#include <stdexcept>

namespace occlusion {

// A bad command line or configuration (unknown key, wrong type, bad value).
// The CLI maps it to exit code 2, the server to an "invalid_request" reply.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace occlusion
