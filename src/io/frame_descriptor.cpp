#include "frame_descriptor.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "json_line.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/named_paths.hpp"
#include "occlusion/io/pose_file.hpp"
#include "occlusion/io/strict_json.hpp"

namespace occlusion::detail {
namespace {

constexpr const char* kFields =
    "depth, colour, intrinsics, depth_scale, pose_tum, camera_to_world, name";
class DescriptorParser {
 public:
  explicit DescriptorParser(const std::string& path) : path_(path), text_(read_file_bytes(path)) {}

  FrameDescriptor parse() {
    const Json::Value root = parse_json();
    if (!root.isObject()) fail(root, "a frame descriptor is a JSON object {...}");
    for (const std::string& key : root.getMemberNames()) {
      if (key != "depth" && key != "colour" && key != "intrinsics" && key != "depth_scale" &&
          key != "pose_tum" && key != "camera_to_world" && key != "name") {
        fail(root[key], "unknown field '" + key + "' (the fields are " + kFields + ")");
      }
    }
    FrameDescriptor frame;
    frame.depth_path = image_path(root, "depth", true);
    const std::string colour = image_path(root, "colour", false);
    if (!colour.empty()) frame.colour_path = colour;
    read_intrinsics(root, frame);
    frame.depth_scale = positive(root, root["depth_scale"], "depth_scale",
                                 "depth values per metre: TUM 5000, Redwood, ScanNet and NYU "
                                 "(as exported to PNG) 1000");
    if (root.isMember("pose_tum") && root.isMember("camera_to_world")) {
      fail(root["camera_to_world"], "both 'pose_tum' and 'camera_to_world' give a pose; keep one");
    }
    if (root.isMember("pose_tum")) read_tum_pose(root["pose_tum"], frame);
    if (root.isMember("camera_to_world")) read_matrix_pose(root["camera_to_world"], frame);
    frame.name = default_name();
    if (root.isMember("name")) {
      const Json::Value& name = root["name"];
      if (!name.isString() || name.asString().empty()) fail(name, "'name' is a non-empty string");
      frame.name = name.asString();
    }
    return frame;
  }

 private:
  Json::Value parse_json() const {
    Json::Value root;
    std::string errors;
    // -Infinity parses, so that a lost pose copied in is named as such below.
    if (!parse_strict_json(text_, StrictJson{16, true}, root, errors)) {
      throw InputError(path_, 0, "not a valid frame descriptor (JSON): " + errors);
    }
    return root;
  }

  std::size_t line_of(const Json::Value& value) const { return detail::json_line(text_, value); }

  [[noreturn]] void fail(const Json::Value& value, const std::string& reason) const {
    throw InputError(path_, line_of(value), reason);
  }

  std::string default_name() const {
    std::string name = std::filesystem::path(path_).filename().string();
    return name.substr(0, name.size() - std::string(kFrameDescriptorSuffix).size());
  }

  std::string image_path(const Json::Value& root, const char* key, bool required) const {
    if (!root.isMember(key)) {
      if (required) {
        fail(root, std::string("no '") + key +
                       "' field: give the depth image, a 16-bit PNG, as a path relative to "
                       "this file's folder");
      }
      return {};
    }
    const Json::Value& value = root[key];
    if (!value.isString() || value.asString().empty()) {
      fail(value, std::string("'") + key + "' is a non-empty string: a PNG file's path");
    }
    return resolve_named_path(path_, value.asString());
  }

  double number(const Json::Value& value, const std::string& name) const {
    if (!value.isNumeric() || !std::isfinite(value.asDouble())) {
      fail(value, "'" + name + "' is a finite number");
    }
    return value.asDouble();
  }

  double positive(const Json::Value& parent, const Json::Value& value, const std::string& name,
                  const std::string& meaning) const {
    if (value.isNull()) fail(parent, "no '" + name + "' field (" + meaning + ")");
    const double x = number(value, name);
    if (!(x > 0)) fail(value, "'" + name + "' must be greater than 0 (" + meaning + ")");
    return x;
  }

  void read_intrinsics(const Json::Value& root, FrameDescriptor& frame) const {
    const Json::Value& intrinsics = root["intrinsics"];
    const char* help =
        "'intrinsics' is {\"fx\": ..., \"fy\": ..., \"cx\": ..., \"cy\": ...} in pixels, from the "
        "depth camera's calibration (TUM freiburg1: 517.3, 516.5, 318.6, 255.3)";
    if (!intrinsics.isObject()) fail(intrinsics.isNull() ? root : intrinsics, help);
    for (const std::string& key : intrinsics.getMemberNames()) {
      if (key != "fx" && key != "fy" && key != "cx" && key != "cy") {
        fail(intrinsics[key], "unknown field 'intrinsics." + key + "'; " + help);
      }
    }
    frame.fx = positive(intrinsics, intrinsics["fx"], "intrinsics.fx", "focal length in pixels");
    frame.fy = positive(intrinsics, intrinsics["fy"], "intrinsics.fy", "focal length in pixels");
    for (const char* key : {"cx", "cy"}) {
      if (intrinsics[key].isNull()) fail(intrinsics, std::string("no 'intrinsics.") + key + "'");
    }
    frame.cx = number(intrinsics["cx"], "intrinsics.cx");
    frame.cy = number(intrinsics["cy"], "intrinsics.cy");
  }

  void read_tum_pose(const Json::Value& pose, FrameDescriptor& frame) const {
    if (!pose.isArray() || pose.size() != 7) {
      fail(pose, "'pose_tum' is [tx, ty, tz, qx, qy, qz, qw]: TUM's camera-to-world pose");
    }
    std::vector<double> numbers;
    for (const Json::Value& x : pose) numbers.push_back(number(x, "pose_tum"));
    set_pose(pose, "pose_tum", numbers, PoseFormat::kTum, frame);
  }

  // The checks of every pose (pose_file.hpp): a rigid motion, within its tolerance.
  void set_pose(const Json::Value& pose, const char* name, const std::vector<double>& numbers,
                PoseFormat format, FrameDescriptor& frame) const {
    try {
      const Eigen::Isometry3d motion = pose_from_numbers(numbers, format).scan_to_scene;
      frame.rotation = Eigen::Quaterniond(motion.linear());
      frame.translation = motion.translation();
    } catch (const std::invalid_argument& error) {
      fail(pose, std::string("'") + name + "': " + error.what());
    }
  }

  void read_matrix_pose(const Json::Value& pose, FrameDescriptor& frame) const {
    const char* help =
        "'camera_to_world' is a 4x4 matrix, 4 rows of 4 numbers (as ScanNet's pose files)";
    if (!pose.isArray() || pose.size() != 4) fail(pose, help);
    std::vector<double> numbers;
    for (Json::ArrayIndex r = 0; r < 4; ++r) {
      if (!pose[r].isArray() || pose[r].size() != 4) fail(pose[r], help);
      for (Json::ArrayIndex c = 0; c < 4; ++c) {
        const Json::Value& x = pose[r][c];
        if (x.isNumeric() && !std::isfinite(x.asDouble())) {
          fail(x,
               "'camera_to_world' holds a value that is not finite: ScanNet marks frames "
               "whose pose was lost with -inf; such a frame has no pose to use");
        }
        numbers.push_back(number(x, "camera_to_world"));
      }
    }
    set_pose(pose, "camera_to_world", numbers, PoseFormat::kMatrix, frame);
  }

  const std::string& path_;
  std::string text_;
};

}  // namespace

FrameDescriptor read_frame_descriptor(const std::string& path) {
  return DescriptorParser(path).parse();
}

}  // namespace occlusion::detail
