#pragma once
#include <string>
#include <vector>

namespace occlusion::cli {

// Each returns the process exit code; errors propagate as exceptions that
// main() maps to exit codes.
int run_mesh_occlusion_command(const std::vector<std::string>& args);
int run_cloud_occlusion_command(const std::vector<std::string>& args);
int run_region_growing_command(const std::vector<std::string>& args);
int run_scan_command(const std::vector<std::string>& args);
int run_reconstruct_command(const std::vector<std::string>& args);
int run_evaluate_command(const std::vector<std::string>& args);
int run_study_command(const std::vector<std::string>& args);
int run_serve_command(const std::vector<std::string>& args);

}  // namespace occlusion::cli
