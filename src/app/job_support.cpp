#include "job_support.hpp"

#include <cmath>
#include <filesystem>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"

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
  throw KeyError("format", "must be ply or pcd, got '" + format + "'");
}

void require_positive(double value, const std::string& option) {
  if (!std::isfinite(value) || value <= 0.0) throw UsageError(option + " must be a number > 0");
}

void require_non_negative(double value, const std::string& option) {
  if (!std::isfinite(value) || value < 0.0) throw UsageError(option + " must be a number >= 0");
}

void write_json_report(const std::string& path, const Json::Value& json) {
  write_file_atomically(path, [&](std::ostream& out) { out << format_json(json) << '\n'; });
}

LoadedCloud load_cloud(const std::string& path, bool skip_bad_lines) {
  CloudReadOptions options;
  options.skip_bad_lines = skip_bad_lines;
  CloudReadReport report;
  LoadedCloud loaded;
  loaded.cloud = read_cloud(path, options, &report);
  loaded.dropped_nan = report.dropped_nan;
  loaded.skipped_lines = report.skipped_lines;
  loaded.rooms = report.rooms;
  return loaded;
}

}  // namespace occlusion::job
