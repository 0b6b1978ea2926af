#pragma once
// The command line as a library: the composition root (src/main) hands it
// the arguments of every command but `serve`.

#include <string>
#include <vector>

#include "occlusion/app/errors.hpp"

namespace occlusion::cli {

// Runs `occlusion ARGS...`; returns the exit code. Errors propagate as
// exceptions; exit_code() maps their classification.
int run(const std::vector<std::string>& args);

// The interface contract: 0 success, 2 usage or configuration error, 3 input
// file error, 1 anything else.
int exit_code(ErrorKind kind);

}  // namespace occlusion::cli
