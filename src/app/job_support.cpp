#include "job_support.hpp"

#include <filesystem>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"

namespace occlusion::job {

std::string output_path(const std::string& out, const std::string& input,
                        const std::string& suffix) {
  std::filesystem::path input_path(input);
  // A folder given with a trailing slash has an empty filename: use its name.
  if (input_path.filename().empty()) input_path = input_path.parent_path();
  return (std::filesystem::path(out) / (input_path.stem().string() + suffix)).string();
}

ViewpointChoice::Resolved resolve_for_cloud(const ViewpointChoice& choice,
                                            const PointCloud& cloud) {
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  return choice.resolve(lo.cast<double>(), hi.cast<double>());
}

Json::Value viewpoint_json(const std::string& name, const Eigen::Vector3d& position) {
  Json::Value json(Json::objectValue);
  json["name"] = name;
  json["position"] = to_json(position);
  return json;
}

std::string cloud_extension(const std::string& format) {
  if (format == "ply" || format == "pcd") return format;
  throw UsageError("--format must be ply or pcd, got '" + format + "'");
}

}  // namespace occlusion::job
