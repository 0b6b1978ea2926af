// 3DTK's scan files, scanNNN.3d (its `uos` layouts), in metres in the tool's
// frame. 3DTK's own reader (src/scanio/helper.cc, readASCII) takes lines of
// whitespace-separated numbers in the layout's columns, `#` comments, and
// skips a few unreadable lines at the top (its old `W x H` resolution line);
// points are in centimetres, left-handed, y up (pose_file.hpp).

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>

#include "cloud_formats.hpp"
#include "file_names.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/named_paths.hpp"
#include "occlusion/io/pose_file.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {
namespace {

enum class Column { kCoordinate, kReflectance, kColour, kTemperature, kType };

struct UosLayoutColumns {
  UosLayout layout;
  const char* name;
  std::vector<Column> after_xyz;
};

const std::vector<UosLayoutColumns>& uos_layouts() {
  using C = Column;
  static const std::vector<UosLayoutColumns> layouts{
      {UosLayout::kXyz, "uos", {}},
      {UosLayout::kReflectance, "uosr", {C::kReflectance}},
      {UosLayout::kRgb, "uos_rgb", {C::kColour, C::kColour, C::kColour}},
      {UosLayout::kRgbReflectance,
       "uos_rgbr",
       {C::kColour, C::kColour, C::kColour, C::kReflectance}},
      {UosLayout::kReflectanceRgb,
       "uos_rrgb",
       {C::kReflectance, C::kColour, C::kColour, C::kColour}},
      {UosLayout::kReflectanceRgbTemperature,
       "uos_rrgbt",
       {C::kReflectance, C::kColour, C::kColour, C::kColour, C::kTemperature}},
      {UosLayout::kType, "uosc", {C::kType}},
  };
  return layouts;
}

const UosLayoutColumns& columns_of(UosLayout layout) {
  for (const UosLayoutColumns& columns : uos_layouts()) {
    if (columns.layout == layout) return columns;
  }
  return uos_layouts().front();
}

// 3DTK's old first line, the scan's resolution: `W x H`.
bool is_resolution_line(std::string_view line) {
  Tokens tokens(line);
  std::int64_t width = 0, height = 0;
  return parse_whole_number(tokens.next(), width) && tokens.next() == "x" &&
         parse_whole_number(tokens.next(), height) && tokens.next().empty();
}

std::size_t column_count(std::string_view line) {
  Tokens tokens(line);
  std::size_t count = 0;
  while (!tokens.next().empty()) ++count;
  return count;
}

class UosParser {
 public:
  UosParser(const std::string& path, std::optional<UosLayout> layout,
            const std::optional<ScanPose>& pose, const CloudReadOptions& options,
            CloudReadReport& report)
      : path_(path), layout_(layout), pose_(pose), report_(report), shifted_(options) {}

  PointCloud run(std::string_view text) {
    Lines lines(without_byte_order_mark(text));
    std::string_view line;
    bool first = true;
    while (lines.next(line)) {
      const std::size_t comment = line.find('#');
      if (comment != std::string_view::npos) line = line.substr(0, comment);
      if (is_blank_line(line)) continue;
      if (first && is_resolution_line(line)) {
        first = false;
        continue;
      }
      first = false;
      if (!columns_) settle_layout(line, lines.number());
      parse(line, lines.number());
    }
    cloud_.shift = shifted_.checked_shift(path_);
    add_station();
    return std::move(cloud_);
  }

 private:
  void settle_layout(std::string_view line, std::size_t number) {
    const std::size_t count = column_count(line);
    if (!layout_) {
      if (count != 3) {
        throw InputError(
            path_, number,
            std::to_string(count) +
                " columns: 3DTK's layouts beyond x y z cannot be told apart by their count "
                "(uos_rgb and uos_normal have 6, uos_rgbr and uos_rrgb 7); name it in a "
                "project file's \"layout\" (" +
                uos_layout_names() + "; docs/formats.md)");
      }
      layout_ = UosLayout::kXyz;
    }
    columns_ = &columns_of(*layout_);
    for (const Column column : columns_->after_xyz) {
      if (column == Column::kColour) has_colour_ = true;
      if (column == Column::kReflectance) has_reflectance_ = true;
      // Values the cloud has no slot for, returned as the PLY and PCD readers return theirs.
      if (column == Column::kTemperature || column == Column::kType) {
        extra_ = report_.extra_fields.size();
        report_.extra_fields.push_back(
            {column == Column::kType ? "type" : "temperature", {}, column == Column::kType});
      }
    }
  }

  void parse(std::string_view line, std::size_t number) {
    const std::size_t expected = 3 + columns_->after_xyz.size();
    double xyz[3];
    std::array<std::uint8_t, 3> rgb{};
    float reflectance = 0, extra_value = 0;
    Tokens tokens(line);
    std::size_t colour = 0;
    for (std::size_t k = 0; k < expected; ++k) {
      const std::string_view token = tokens.next();
      if (token.empty()) {
        throw InputError(path_, number,
                         std::to_string(k) + " columns; the layout " + columns_->name + " has " +
                             std::to_string(expected));
      }
      const Column column = k < 3 ? Column::kCoordinate : columns_->after_xyz[k - 3];
      double value = 0;
      if (!parse_double(token, value)) {
        throw InputError(path_, number, quoted(token) + " is not a number");
      }
      switch (column) {
        case Column::kCoordinate:
          xyz[k] = value;
          break;
        case Column::kColour: {
          std::int64_t channel = 0;
          if (!parse_whole_number(token, channel) || channel < 0 || channel > 255) {
            throw InputError(path_, number,
                             "colour " + quoted(token) + " is not a whole number in 0..255");
          }
          rgb[colour++] = static_cast<std::uint8_t>(channel);
          break;
        }
        case Column::kReflectance:
          reflectance = static_cast<float>(value);
          break;
        case Column::kTemperature:
        case Column::kType:
          extra_value = static_cast<float>(value);
          break;
      }
    }
    if (!tokens.next().empty()) {
      throw InputError(path_, number,
                       "more than " + std::to_string(expected) + " columns; the layout " +
                           columns_->name + " has " + std::to_string(expected));
    }
    Eigen::Vector3d point = point_from_3dtk(Eigen::Vector3d(xyz[0], xyz[1], xyz[2]));
    if (pose_) point = pose_->scan_to_scene * point;
    const Eigen::Vector3f position = shifted_.local(point.data());
    if (!position.allFinite()) {
      ++report_.dropped_nan;
      return;
    }
    cloud_.positions.push_back(position);
    if (has_colour_) cloud_.colours.push_back(rgb);
    if (has_reflectance_) cloud_.intensities.push_back(reflectance);
    if (extra_) report_.extra_fields[*extra_].values.push_back(extra_value);
  }

  // The scan is one scanner's station: at its pose, else at the origin of
  // the scanner's frame.
  void add_station() {
    Station station;
    station.name = std::filesystem::path(path_).stem().string();
    if (pose_) {
      station.frame.origin = cloud_.to_local(pose_->scan_to_scene.translation());
      station.frame.orientation = Eigen::Quaterniond(pose_->scan_to_scene.linear());
    } else {
      station.frame.origin = cloud_.to_local(Eigen::Vector3d::Zero());
    }
    cloud_.stations.push_back(station);
    cloud_.station_ids.assign(cloud_.size(), 0);
  }

  const std::string& path_;
  std::optional<UosLayout> layout_;
  const std::optional<ScanPose>& pose_;  // from the sibling .pose
  CloudReadReport& report_;
  ShiftedPositions shifted_;
  PointCloud cloud_;
  const UosLayoutColumns* columns_ = nullptr;
  bool has_colour_ = false;
  bool has_reflectance_ = false;
  std::optional<std::size_t> extra_;  // the index of the temperature or type field in the report
};

}  // namespace

std::optional<UosLayout> uos_layout_from_name(std::string_view name) {
  for (const UosLayoutColumns& columns : uos_layouts()) {
    if (name == columns.name) return columns.layout;
  }
  return std::nullopt;
}

std::string uos_layout_names() {
  std::string names;
  for (const UosLayoutColumns& columns : uos_layouts()) {
    names += (names.empty() ? "" : ", ") + std::string(columns.name);
  }
  return names;
}

std::string uos_sibling_pose(const std::string& path) {
  const std::string name =
      std::filesystem::path(path).filename().replace_extension(".pose").string();
  const std::string pose = resolve_named_path(path, name);
  std::error_code status;
  return std::filesystem::is_regular_file(pose, status) ? pose : std::string();
}

PointCloud read_uos_scan(const std::string& path, std::optional<UosLayout> layout,
                         const CloudReadOptions& options, CloudReadReport& report) {
  std::optional<ScanPose> pose;
  if (const std::string pose_path = uos_sibling_pose(path); !pose_path.empty()) {
    pose = read_pose_file(pose_path, PoseFormat::k3dtk);
  }
  const std::string bytes = read_file_bytes(path);
  return UosParser(path, layout, pose, options, report).run(bytes);
}

PointCloud read_uos(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report) {
  return read_uos_scan(path, std::nullopt, options, report);
}

}  // namespace occlusion::detail
