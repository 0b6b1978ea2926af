#pragma once
#include <string>
#include <vector>

namespace occlusion::cli {

// Each returns the process exit code; errors propagate as exceptions that
// main() maps to exit codes.
int run_mesh_occlusion_command(const std::vector<std::string>& args);
void print_mesh_occlusion_help();

}  // namespace occlusion::cli
