// NAME.project.json: the scans of a scene with their poses (scene_project.hpp).

#include <json/writer.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <ostream>
#include <stdexcept>

#include "cloud_formats.hpp"
#include "file_names.hpp"
#include "json_line.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/named_paths.hpp"
#include "occlusion/io/scene_project.hpp"
#include "occlusion/io/strict_json.hpp"

namespace occlusion {
namespace {

constexpr const char* kScanFieldNames[] = {"path",    "pose",   "pose_file", "pose_format",
                                           "station", "layout", "units"};
constexpr const char* kScanFields = "path, pose, pose_file, pose_format, station, layout, units";

bool is_scan_field(const std::string& key) {
  return std::any_of(std::begin(kScanFieldNames), std::end(kScanFieldNames),
                     [&](const char* name) { return key == name; });
}

struct Unit {
  const char* name;
  double metres;
};
constexpr Unit kUnits[] = {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}};

class ProjectParser {
 public:
  explicit ProjectParser(const std::string& path) : path_(path), text_(read_file_bytes(path)) {}

  std::vector<SceneScan> parse() {
    Json::Value root;
    std::string errors;
    if (!parse_strict_json(text_, StrictJson{}, root, errors)) {
      throw InputError(path_, 0, "not a valid project file (JSON): " + errors);
    }
    if (!root.isObject()) fail(root, "a project file is a JSON object {\"scans\": [...]}");
    for (const std::string& key : root.getMemberNames()) {
      if (key != "scans") fail(root[key], "unknown field '" + key + "' (the field is scans)");
    }
    const Json::Value& scans = root["scans"];
    if (!scans.isArray() || scans.empty()) {
      fail(scans.isNull() ? root : scans,
           "'scans' is a non-empty list of scans, each {\"path\": ..., \"pose\": ...}");
    }
    std::vector<SceneScan> result;
    for (const Json::Value& scan : scans) result.push_back(parse_scan(scan));
    return result;
  }

 private:
  SceneScan parse_scan(const Json::Value& scan) const {
    if (!scan.isObject()) fail(scan, "each scan is an object {\"path\": ..., \"pose\": ...}");
    for (const std::string& key : scan.getMemberNames()) {
      if (!is_scan_field(key)) {
        fail(scan[key], "unknown field '" + key + "' (the fields are " + kScanFields + ")");
      }
    }
    SceneScan result;
    result.line = line_of(scan);
    const std::string path = text(scan, "path");
    if (path.empty()) fail(scan, "no 'path': the scan's file, relative to this file's folder");
    if (is_project_file(path)) {
      fail(scan["path"], "a project's scan cannot be a project: list its scans here");
    }
    result.named_path = path;
    result.path = resolve_named_path(path_, path);
    result.station = text(scan, "station");
    if (scan.isMember("station") && result.station.empty()) {
      fail(scan["station"], "'station' is a non-empty name");
    }
    result.layout = text(scan, "layout");
    if (!result.layout.empty() && !detail::uos_layout_from_name(result.layout)) {
      fail(scan["layout"],
           "unknown layout '" + result.layout + "' (3DTK's: " + detail::uos_layout_names() + ")");
    }
    if (!result.layout.empty() && detail::lower_extension(path) != ".3d") {
      fail(scan["layout"], "'layout' is a 3DTK .3d file's; this scan is no .3d file");
    }
    read_units(scan, result);
    read_pose(scan, result);
    return result;
  }

  void read_units(const Json::Value& scan, SceneScan& result) const {
    if (!scan.isMember("units")) return;
    const std::string units = text(scan, "units");
    for (const Unit& unit : kUnits) {
      if (units == unit.name) {
        if (detail::lower_extension(result.path) == ".3d" && unit.metres != 1.0) {
          fail(scan["units"], "a 3DTK .3d file is in centimetres by its format; leave 'units' out");
        }
        result.metres_per_unit = unit.metres;
        return;
      }
    }
    fail(scan["units"], "'units' is the scan's coordinates' unit: m, cm or mm");
  }

  void read_pose(const Json::Value& scan, SceneScan& result) const {
    const bool inline_pose = scan.isMember("pose");
    const bool file_pose = scan.isMember("pose_file");
    if (inline_pose && file_pose) {
      fail(scan["pose_file"], "both 'pose' and 'pose_file' give a pose; keep one");
    }
    std::optional<PoseFormat> format;
    if (scan.isMember("pose_format")) {
      const std::string name = text(scan, "pose_format");
      format = pose_format_from_name(name);
      if (!format) {
        fail(scan["pose_format"],
             "unknown pose format '" + name + "' (the formats are " + pose_format_names() + ")");
      }
      if (!inline_pose && !file_pose) fail(scan["pose_format"], "'pose_format' without a pose");
    }
    if (file_pose) {
      const std::string file = text(scan, "pose_file");
      if (file.empty()) fail(scan["pose_file"], "'pose_file' is a path, relative to this file");
      result.named_pose_file = file;
      result.pose_path = resolve_named_path(path_, file);
      result.pose = read_pose_file(result.pose_path, format);
    }
    if (inline_pose) result.pose = inline_numbers(scan["pose"], format);
  }

  // [[r0], [r1], [r2], [r3]] is a matrix in rows; a flat list needs its format.
  ScanPose inline_numbers(const Json::Value& pose, std::optional<PoseFormat> format) const {
    const char* help =
        "'pose' is a 4 x 4 matrix in rows [[...], [...], [...], [...]], or a flat list of "
        "numbers with its 'pose_format' (tum: tx ty tz qx qy qz qw; 3dtk: tx ty tz in cm, ax ay az "
        "in degrees)";
    if (!pose.isArray() || pose.empty()) fail(pose, help);
    std::vector<double> numbers;
    const bool rows = pose[0].isArray();
    if (rows) {
      if (format && *format != PoseFormat::kMatrix) fail(pose, help);
      format = PoseFormat::kMatrix;
      if (pose.size() != 4) fail(pose, help);
      for (const Json::Value& row : pose) {
        if (!row.isArray() || row.size() != 4) fail(row, help);
        for (const Json::Value& x : row) numbers.push_back(number(x));
      }
    } else {
      if (!format) fail(pose, std::string(help) + "; this list has no 'pose_format'");
      for (const Json::Value& x : pose) numbers.push_back(number(x));
    }
    try {
      return pose_from_numbers(numbers, *format);
    } catch (const std::invalid_argument& error) {
      fail(pose, std::string("'pose': ") + error.what());
    }
  }

  double number(const Json::Value& value) const {
    if (!value.isNumeric() || !std::isfinite(value.asDouble())) {
      fail(value, "a pose holds finite numbers only");
    }
    return value.asDouble();
  }

  std::string text(const Json::Value& scan, const char* key) const {
    if (!scan.isMember(key)) return {};
    const Json::Value& value = scan[key];
    if (!value.isString()) fail(value, std::string("'") + key + "' is a string");
    return value.asString();
  }

  std::size_t line_of(const Json::Value& value) const { return detail::json_line(text_, value); }

  [[noreturn]] void fail(const Json::Value& value, const std::string& reason) const {
    throw InputError(path_, line_of(value), reason);
  }

  const std::string& path_;
  std::string text_;
};

std::string unit_name(double metres_per_unit) {
  for (const Unit& unit : kUnits) {
    if (unit.metres == metres_per_unit) return unit.name;
  }
  throw std::invalid_argument("write_project_file: a scan's unit is " +
                              std::to_string(metres_per_unit) + " m, not m, cm or mm");
}

Json::Value scan_json(const SceneScan& scan) {
  Json::Value json(Json::objectValue);
  json["path"] = scan.named_path.empty() ? scan.path : scan.named_path;
  if (scan.pose && !scan.pose_path.empty()) {
    json["pose_file"] = scan.named_pose_file.empty() ? scan.pose_path : scan.named_pose_file;
    json["pose_format"] = std::string(pose_format_name(scan.pose->format));
  } else if (scan.pose) {
    const std::vector<double> numbers = pose_numbers(*scan.pose);
    Json::Value pose(Json::arrayValue);
    if (scan.pose->format == PoseFormat::kMatrix) {
      for (std::size_t r = 0; r < 4; ++r) {
        Json::Value row(Json::arrayValue);
        for (std::size_t c = 0; c < 4; ++c) row.append(numbers[4 * r + c]);
        pose.append(row);
      }
    } else {
      for (const double x : numbers) pose.append(x);
      json["pose_format"] = std::string(pose_format_name(scan.pose->format));
    }
    json["pose"] = pose;
  }
  if (!scan.station.empty()) json["station"] = scan.station;
  if (!scan.layout.empty()) json["layout"] = scan.layout;
  if (scan.metres_per_unit != 1.0) json["units"] = unit_name(scan.metres_per_unit);
  return json;
}

}  // namespace

void write_project_file(const std::string& path, const std::vector<SceneScan>& scans) {
  Json::Value root(Json::objectValue);
  Json::Value& list = root["scans"] = Json::Value(Json::arrayValue);
  for (const SceneScan& scan : scans) list.append(scan_json(scan));
  Json::StreamWriterBuilder writer;
  writer["indentation"] = "  ";
  writer["precision"] = 17;
  const std::string text = Json::writeString(writer, root) + "\n";
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

bool is_project_file(const std::string& path) {
  return detail::has_suffix(path, kProjectFileSuffix);
}

std::vector<SceneScan> read_project_file(const std::string& path) {
  return ProjectParser(path).parse();
}

}  // namespace occlusion
