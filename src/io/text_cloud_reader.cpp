#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "cloud_formats.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {
namespace {

constexpr int kMaxColumns = 7;
constexpr const char* kLayouts =
    "x y z (3), x y z label (4), x y z r g b (6) or x y z r g b label (7)";

bool is_comment(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos) return false;
  return line[first] == '#' || line.compare(first, 2, "//") == 0;
}

// One line's values before they join the cloud, so a bad line adds nothing.
struct TextPoint {
  double xyz[3] = {0, 0, 0};
  std::array<std::uint8_t, 3> rgb{};
  std::int64_t label = -1;
};

class TextCloudParser {
 public:
  TextCloudParser(std::string_view text, const std::string& source,
                  std::optional<int> required_columns, const CloudReadOptions& options,
                  CloudReadReport& report)
      : text_(text),
        source_(source),
        columns_(required_columns.value_or(0)),
        columns_fixed_(required_columns.has_value()),
        options_(options),
        report_(report),
        shifted_(options) {}

  PointCloud run() {
    // A UTF-8 byte order mark, which some Windows editors add, is not data.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);
    auto line_count = static_cast<std::size_t>(std::count(text_.begin(), text_.end(), '\n'));
    // Room for the points the reader may keep, not for every line of a file it stops in.
    if (options_.max_points != 0) line_count = std::min(line_count, options_.max_points);
    cloud_.reserve_positions(line_count + 1);
    if (columns_fixed_ && columns_ >= 6) cloud_.colours.reserve(line_count + 1);
    Lines lines(text_);
    std::string_view line;
    while (lines.next(line)) {
      if (is_blank_line(line) || is_comment(line)) continue;
      TextPoint point;
      std::string problem = parse_line(line, lines.number(), point);
      if (!problem.empty()) {
        if (!options_.skip_bad_lines) throw InputError(source_, lines.number(), problem);
        ++report_.skipped_lines;
        continue;
      }
      add(point);
    }
    cloud_.shift = shifted_.checked_shift(source_);
    return std::move(cloud_);
  }

 private:
  std::string parse_line(std::string_view line, std::size_t line_number, TextPoint& point) {
    std::string_view tokens[kMaxColumns + 1];
    int count = 0;
    Tokens splitter(line);
    for (std::string_view token = splitter.next(); !token.empty() && count <= kMaxColumns;
         token = splitter.next()) {
      tokens[count++] = token;
    }
    if (std::string problem = check_column_count(count); !problem.empty()) return problem;

    for (int axis = 0; axis < 3; ++axis) {
      if (!parse_double(tokens[axis], point.xyz[axis])) {
        return "coordinate " + quoted(tokens[axis]) + " is not a number";
      }
    }
    const bool has_colour = count >= 6;
    if (has_colour) {
      for (int channel = 0; channel < 3; ++channel) {
        std::int64_t value = 0;
        const std::string_view token = tokens[3 + channel];
        if (!parse_whole_number(token, value) || value < 0 || value > 255) {
          return "colour " + quoted(token) + " is not a whole number in 0..255";
        }
        point.rgb[channel] = static_cast<std::uint8_t>(value);
      }
    }
    const bool has_label = count == 4 || count == 7;
    if (has_label) {
      const std::string_view token = tokens[count - 1];
      if (!parse_whole_number(token, point.label)) {
        return "label " + quoted(token) + " is not a whole number";
      }
      if (std::string problem = id_problem(point.label, true, 0); !problem.empty()) return problem;
    }
    // The layout is settled by the first line that parses, not by a corrupt one.
    if (columns_ == 0) {
      columns_ = count;
      columns_line_ = line_number;
      if (has_colour) cloud_.colours.reserve(cloud_.positions.capacity());
      if (has_label) cloud_.labels.reserve(cloud_.positions.capacity());
    }
    return "";
  }

  std::string check_column_count(int count) const {
    const std::string have =
        count > kMaxColumns ? "more than " + std::to_string(kMaxColumns) : std::to_string(count);
    if (columns_fixed_ && count != columns_) {
      return have + " columns; this file must have " + std::to_string(columns_) +
             (columns_ == 6 ? " (x y z r g b)" : "");
    }
    if (columns_ != 0 && count != columns_) {
      return have + " columns, but line " + std::to_string(columns_line_) + " has " +
             std::to_string(columns_) + " (every line must have the same layout)";
    }
    if (count != 3 && count != 4 && count != 6 && count != 7) {
      return have + " columns; expected " + kLayouts;
    }
    return "";
  }

  void add(const TextPoint& point) {
    const Eigen::Vector3f position = shifted_.local(point.xyz);
    if (!position.allFinite()) {
      ++report_.dropped_nan;
      return;
    }
    cloud_.positions.push_back(position);
    if (columns_ >= 6) cloud_.colours.push_back(point.rgb);
    if (columns_ == 4 || columns_ == 7) {
      cloud_.labels.push_back(static_cast<std::int32_t>(point.label));
    }
  }

  std::string_view text_;
  const std::string& source_;
  int columns_;  // 0 until the first good line (unless fixed)
  bool columns_fixed_;
  std::size_t columns_line_ = 0;
  const CloudReadOptions& options_;
  CloudReadReport& report_;
  ShiftedPositions shifted_;
  PointCloud cloud_;
};

}  // namespace

PointCloud parse_text_cloud(std::string_view text, const std::string& source,
                            std::optional<int> required_columns, const CloudReadOptions& options,
                            CloudReadReport& report) {
  return TextCloudParser(text, source, required_columns, options, report).run();
}

PointCloud read_text_cloud(const std::string& path, const CloudReadOptions& options,
                           CloudReadReport& report) {
  const std::string bytes = read_file_bytes(path);
  return parse_text_cloud(bytes, path, std::nullopt, options, report);
}

}  // namespace occlusion::detail
