#pragma once
// Pieces every job's run function shares (internal to app/).

#include <json/value.h>

#include <chrono>
#include <string>
#include <vector>

#include "occlusion/app/viewpoint_choice.hpp"
#include "occlusion/core/point_cloud.hpp"

namespace occlusion::job {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// <out>/<stem of input><suffix>, e.g. ("out", "room.pcd", ".poc.json") -> out/room.poc.json.
std::string output_path(const std::string& out, const std::string& input,
                        const std::string& suffix);

// Viewpoints for a cloud, from its bounding box.
ViewpointChoice::Resolved resolve_for_cloud(const ViewpointChoice& choice, const PointCloud& cloud);

// [{"name": ..., "position": [x, y, z], <figures>...}, ...] built by the caller.
Json::Value viewpoint_json(const std::string& name, const Eigen::Vector3d& position);

// Throws UsageError unless format is "ply" or "pcd"; returns the file extension.
std::string cloud_extension(const std::string& format);

// Option checks shared by the jobs; each throws UsageError naming the option.
void require_positive(double value, const std::string& option);
void require_non_negative(double value, const std::string& option);

// Writes a job's JSON report atomically.
void write_json_report(const std::string& path, const Json::Value& json);

// A cloud as the point-cloud jobs load it, with what reading dropped or skipped.
struct LoadedCloud {
  PointCloud cloud;
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> rooms;
  std::vector<std::string> unverified_order;  // CloudReadReport::unverified_order
  std::vector<std::size_t> annotation_order;  // CloudReadReport::annotation_order
};
LoadedCloud load_cloud(const std::string& path, bool skip_bad_lines);

}  // namespace occlusion::job
