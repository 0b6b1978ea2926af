// Our own PLY reader rather than PCL's: an error must give its line or byte
// offset, any vertex layout other tools write must map onto the cloud, and the
// class names ride in header comments that PCL drops.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cloud_formats.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "ply_body.hpp"
#include "ply_header.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {
namespace {

// Where each vertex property goes in the cloud.
enum class Role {
  kX,
  kY,
  kZ,
  kRed,
  kGreen,
  kBlue,
  kLabel,
  kInstance,
  kIntensity,
  kStation,
  kExtra,
  kSkip
};

// `has_stations`: the header records stations, so a `scan` property indexes them.
Role role_of(const PlyProperty& property, bool has_stations) {
  if (property.is_list) return Role::kSkip;
  const std::string& name = property.name;
  if (name == "x") return Role::kX;
  if (name == "y") return Role::kY;
  if (name == "z") return Role::kZ;
  if (name == "red" || name == "r" || name == "diffuse_red") return Role::kRed;
  if (name == "green" || name == "g" || name == "diffuse_green") return Role::kGreen;
  if (name == "blue" || name == "b" || name == "diffuse_blue") return Role::kBlue;
  // Per-point values may carry CloudCompare's scalar_ prefix (cloud_formats.hpp).
  const std::string_view value_name = without_scalar_prefix(name);
  if (is_label_name(value_name)) return Role::kLabel;
  if (is_instance_name(value_name)) return Role::kInstance;
  if (is_intensity_name(value_name)) return Role::kIntensity;
  if (has_stations && value_name == kStationIdName) return Role::kStation;
  return Role::kExtra;
}

const char* role_name(Role role) {
  switch (role) {
    case Role::kX:
      return "x";
    case Role::kY:
      return "y";
    case Role::kZ:
      return "z";
    case Role::kRed:
      return "red";
    case Role::kGreen:
      return "green";
    case Role::kBlue:
      return "blue";
    case Role::kLabel:
      return "label";
    case Role::kInstance:
      return "instance";
    case Role::kIntensity:
      return "intensity";
    case Role::kStation:
      return "scan";
    default:
      return "";
  }
}

class PlyCloudReader : public PlySink {
 public:
  PlyCloudReader(std::string_view bytes, const std::string& path, const CloudReadOptions& options,
                 CloudReadReport& report)
      : bytes_(bytes), path_(path), report_(report), shifted_(options) {}

  PointCloud run() {
    header_ = parse_header(bytes_, path_);
    assign_roles();
    cloud_.class_names = header_.class_names;
    cloud_.stations = header_.stations;
    extra_values_.assign(extra_.size(), 0.0f);
    read_ply_body(bytes_, path_, header_, *this);
    if (float_colours_) cloud_.colours = colours_from_floats(float_rgb_, path_);
    for (std::size_t f = 0; f < extra_.size(); ++f) {
      report_.extra_fields.push_back(std::move(extra_[f]));
    }
    cloud_.shift = shifted_.checked_shift(path_);
    for (Station& station : cloud_.stations) {
      station.frame.origin = cloud_.to_local(station.frame.origin);
    }
    return std::move(cloud_);
  }

 private:
  bool wants(std::size_t e) const override { return e == vertex_element_; }

  std::string take(std::size_t, std::size_t p, std::size_t, double value) override {
    return take(p, value);
  }

  std::string end_instance(std::size_t) override {
    commit_vertex();
    return "";
  }

  void assign_roles() {
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      if (header_.elements[e].name == "vertex") {
        vertex_element_ = e;
        break;
      }
    }
    if (vertex_element_ == kNone) throw InputError(path_, 0, "the header has no vertex element");
    const PlyElement& vertex = header_.elements[vertex_element_];
    bool seen[static_cast<int>(Role::kExtra)] = {};
    for (const PlyProperty& property : vertex.properties) {
      const Role role = role_of(property, !header_.stations.empty());
      roles_.push_back(role);
      extra_index_.push_back(kNone);
      if (role == Role::kExtra) {
        extra_index_.back() = extra_.size();
        extra_.push_back(
            {std::string(without_scalar_prefix(property.name)), {}, is_integer(property.type)});
        continue;
      }
      if (role == Role::kSkip) continue;
      if (seen[static_cast<int>(role)]) {
        throw InputError(path_, vertex.line,
                         std::string("the vertex element has two ") + role_name(role) +
                             " properties (" + property.name + " is the second)");
      }
      seen[static_cast<int>(role)] = true;
      const bool colour = role == Role::kRed || role == Role::kGreen || role == Role::kBlue;
      if (colour) {
        const ColourType kind =
            is_integer(property.type) ? ColourType::kInteger : ColourType::kFloat;
        if (colour_type_ != ColourType::kNone && colour_type_ != kind) {
          throw InputError(
              path_, vertex.line,
              "colour property '" + property.name + "' mixes integer and floating-point channels");
        }
        colour_type_ = kind;
      }
    }
    for (const Role axis : {Role::kX, Role::kY, Role::kZ}) {
      if (!seen[static_cast<int>(axis)]) {
        throw InputError(
            path_, vertex.line,
            std::string("the vertex element has no scalar '") + role_name(axis) + "' property");
      }
    }
    const int colours = int{seen[static_cast<int>(Role::kRed)]} +
                        int{seen[static_cast<int>(Role::kGreen)]} +
                        int{seen[static_cast<int>(Role::kBlue)]};
    if (colours != 0 && colours != 3) {
      throw InputError(path_, vertex.line,
                       "the vertex element has some but not all of red green blue");
    }
    has_colours_ = colours == 3;
    float_colours_ = has_colours_ && colour_type_ == ColourType::kFloat;
    has_labels_ = seen[static_cast<int>(Role::kLabel)];
    has_instances_ = seen[static_cast<int>(Role::kInstance)];
    has_intensities_ = seen[static_cast<int>(Role::kIntensity)];
    has_station_ids_ = seen[static_cast<int>(Role::kStation)];

    // Capped by the file size, so a header that claims billions of vertices
    // fails as truncated instead of exhausting memory first.
    const std::size_t reserve = std::min(vertex.count, bytes_.size() / 4);
    cloud_.reserve_positions(reserve);
    if (has_colours_ && !float_colours_) cloud_.colours.reserve(reserve);
    if (float_colours_) float_rgb_.reserve(3 * reserve);
    if (has_labels_) cloud_.labels.reserve(reserve);
    if (has_instances_) cloud_.instances.reserve(reserve);
    if (has_intensities_) cloud_.intensities.reserve(reserve);
    if (has_station_ids_) cloud_.station_ids.reserve(reserve);
    for (ScalarField& field : extra_) field.values.reserve(reserve);
  }

  // Checks one vertex property value and keeps it for the vertex being read.
  // Returns the problem, or "" if the value is usable.
  std::string take(std::size_t p, double value) {
    const Role role = roles_[p];
    switch (role) {
      case Role::kX:
      case Role::kY:
      case Role::kZ:
        xyz_[static_cast<int>(role)] = value;
        return "";
      case Role::kRed:
      case Role::kGreen:
      case Role::kBlue:
        if (!(value >= 0 && value <= 255)) {
          return std::string(role_name(role)) + " value " + number_text(value) +
                 " is outside 0..255";
        }
        if (float_colours_) {
          float_channels_[static_cast<int>(role) - static_cast<int>(Role::kRed)] =
              static_cast<float>(value);
          return "";
        }
        rgb_[static_cast<int>(role) - static_cast<int>(Role::kRed)] =
            static_cast<std::uint8_t>(value);
        return "";
      case Role::kLabel:
      case Role::kInstance: {
        const bool is_label = role == Role::kLabel;
        if (!std::isfinite(value) || value != std::floor(value) || std::fabs(value) > 9e15) {
          return std::string(role_name(role)) + " value " + number_text(value) +
                 " is not a whole number";
        }
        const auto id = static_cast<std::int64_t>(value);
        std::string problem = id_problem(id, is_label, cloud_.class_names.size());
        if (!problem.empty()) return problem;
        (is_label ? label_ : instance_) = static_cast<std::int32_t>(id);
        return "";
      }
      case Role::kIntensity:
        intensity_ = static_cast<float>(value);
        return "";
      case Role::kStation:
        if (!(value >= 0 && value < static_cast<double>(header_.stations.size())) ||
            value != std::floor(value)) {
          return "scan value " + number_text(value) + " names no station (the header records " +
                 std::to_string(header_.stations.size()) + ")";
        }
        station_ = static_cast<std::int32_t>(value);
        return "";
      case Role::kExtra:
        extra_values_[extra_index_[p]] = static_cast<float>(value);
        return "";
      case Role::kSkip:
        return "";
    }
    return "";
  }

  static std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
  }

  void commit_vertex() {
    const Eigen::Vector3f position = shifted_.local(xyz_);
    if (!position.allFinite()) {
      ++report_.dropped_nan;
      return;
    }
    cloud_.positions.push_back(position);
    if (float_colours_) {
      float_rgb_.insert(float_rgb_.end(), float_channels_, float_channels_ + 3);
    } else if (has_colours_) {
      cloud_.colours.push_back(rgb_);
    }
    if (has_labels_) cloud_.labels.push_back(label_);
    if (has_instances_) cloud_.instances.push_back(instance_);
    if (has_intensities_) cloud_.intensities.push_back(intensity_);
    if (has_station_ids_) cloud_.station_ids.push_back(station_);
    for (std::size_t f = 0; f < extra_.size(); ++f) extra_[f].values.push_back(extra_values_[f]);
  }

  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

  std::string_view bytes_;
  const std::string& path_;
  CloudReadReport& report_;
  PlyHeader header_;
  std::size_t vertex_element_ = kNone;
  std::vector<Role> roles_;               // per vertex property
  std::vector<std::size_t> extra_index_;  // per vertex property: its extra field, or kNone
  std::vector<ScalarField> extra_;
  bool has_colours_ = false;
  enum class ColourType { kNone, kInteger, kFloat };
  ColourType colour_type_ = ColourType::kNone;  // of the colour properties seen so far
  bool float_colours_ = false;
  std::vector<float> float_rgb_;  // float colours, 3 per kept point, scaled once all are read
  float float_channels_[3] = {0, 0, 0};
  bool has_labels_ = false;
  bool has_instances_ = false;
  bool has_intensities_ = false;
  bool has_station_ids_ = false;
  ShiftedPositions shifted_;
  PointCloud cloud_;

  // The vertex being read, committed once all its properties are checked.
  double xyz_[3] = {0, 0, 0};
  std::array<std::uint8_t, 3> rgb_{};
  std::int32_t label_ = -1;
  std::int32_t instance_ = -1;
  float intensity_ = 0.0f;
  std::int32_t station_ = 0;
  std::vector<float> extra_values_;
};

}  // namespace

PointCloud read_ply(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report) {
  const LargeString bytes = read_file_bytes<LargeString>(path);
  return PlyCloudReader(bytes, path, options, report).run();
}

}  // namespace occlusion::detail
