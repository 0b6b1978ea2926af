#pragma once
// The `register` job: a source scan's pose onto a target scan, refined from
// an initial pose (analysis/registration.hpp), written back in the format the
// initial pose was given in, with a JSON report of the fit.

#include <json/value.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/registration.hpp"
#include "occlusion/app/key.hpp"

namespace occlusion {

struct RegisterRequest {
  std::string path;                  // the source scan, in its scanner's frame
  std::string target;                // the scan it is registered onto
  std::string initial_pose;          // pose file: source frame -> target frame
  std::string pose_format = "auto";  // of initial_pose: auto, matrix, tum or 3dtk
  std::string method = registration_method_name(RegistrationOptions{}.method);
  unsigned levels = RegistrationOptions{}.levels;
  std::optional<double> finest_voxel;  // auto: from the point spacing
  std::optional<double> max_distance;  // auto: from the coarsest voxel
  unsigned max_iterations = RegistrationOptions{}.max_iterations;
  double min_overlap = RegistrationOptions{}.min_overlap;
  double max_rotation = RegistrationOptions{}.max_rotation_deg;
  bool skip_bad_lines = false;
  unsigned threads = 0;
  std::string out;
};

// One scan of a project registered onto the project's first scan.
struct ProjectScanRegistration {
  std::string path;
  std::size_t points = 0;
  RegistrationResult result;
};

struct RegisterReport {
  RegisterRequest request;
  RegistrationResult result;  // a pair's; a project's last scan's
  // A project file's scans after the first, each registered onto the first
  // (empty for a pair).
  std::vector<ProjectScanRegistration> project_scans;
  std::string pose_format;  // of the initial pose file, and so of the refined one
  std::size_t source_points = 0, target_points = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0;
  double total_seconds = 0.0;
};

void validate(const RegisterRequest& request);
// Every key of the job (config section occlusion.register), declared once.
const Keys<RegisterRequest>& register_keys();
// InputError naming the source for a pair registration refuses (what() says
// why and what to do).
RegisterReport run_register(const RegisterRequest& request, const Progress& progress = {});
RegistrationOptions registration_options(const RegisterRequest& request);
// Headline: rms and overlap after registration.
Json::Value to_json(const RegisterReport& report);
// A pose as JSON: matrix (rows), translation and rotation (axis-angle degrees).
Json::Value pose_json(const Eigen::Isometry3d& pose);

}  // namespace occlusion
