#pragma once
// The `reconstruct` job (-recon): an S3DIS room folder (or a whole Area_N
// folder) into one labelled cloud plus a JSON summary of points per class.

#include <json/value.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "occlusion/app/key.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct ReconstructRequest {
  std::string path;            // room or Area folder
  std::string format = "ply";  // ply or pcd
  bool skip_bad_lines = false;
  std::string out = ".";  // folder receiving <name>.<format> and <name>.recon.json
};

struct ClassCount {
  std::string name;
  std::size_t points = 0;
  std::size_t instances = 0;
};

struct ReconstructReport {
  ReconstructRequest request;
  std::size_t points = 0;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // the cloud's global shift, written back
  std::vector<ClassCount> classes;
  std::vector<std::string> rooms;
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double total_seconds = 0.0;
};

void validate(const ReconstructRequest& request);
// Every key of the job (config section occlusion.reconstruct), declared once.
const Keys<ReconstructRequest>& reconstruct_keys();
ReconstructReport run_reconstruct(const ReconstructRequest& request, const Progress& progress = {});
Json::Value to_json(const ReconstructReport& report);

}  // namespace occlusion
