#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_set>

#include "cloud_formats.hpp"
#include "number_text.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {

std::string_view without_scalar_prefix(std::string_view name) {
  if (name.size() > kPlyScalarPrefix.size() &&
      name.substr(0, kPlyScalarPrefix.size()) == kPlyScalarPrefix) {
    name.remove_prefix(kPlyScalarPrefix.size());
  }
  return name;
}

bool is_label_name(std::string_view name) {
  return name == "label" || name == "class";
}

bool is_instance_name(std::string_view name) {
  return name == "instance" || name == "instance_id" || name == "object" || name == "object_id";
}

bool is_intensity_name(std::string_view name) {
  return name == kIntensityName || name == "Intensity";
}

namespace {

void append_quoted(std::string& text, const std::string& name) {
  text += '"';
  for (const char c : name) {
    switch (c) {
      case '"':
        text += "\\\"";
        break;
      case '\\':
        text += "\\\\";
        break;
      case '\n':
        text += "\\n";
        break;
      case '\r':
        text += "\\r";
        break;
      case '\t':
        text += "\\t";
        break;
      default:
        text += c;
    }
  }
  text += '"';
}

// The quoted name at the start of `text` (which it advances past it), or
// std::invalid_argument.
std::string take_quoted(std::string_view& text) {
  if (text.empty() || text.front() != '"') {
    throw std::invalid_argument("a station's name must be in double quotes");
  }
  std::string name;
  for (std::size_t i = 1; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      text.remove_prefix(i + 1);
      return name;
    }
    if (c != '\\') {
      name += c;
      continue;
    }
    if (++i == text.size()) break;
    switch (text[i]) {
      case '"':
      case '\\':
        name += text[i];
        break;
      case 'n':
        name += '\n';
        break;
      case 'r':
        name += '\r';
        break;
      case 't':
        name += '\t';
        break;
      default:
        throw std::invalid_argument(std::string("a station's name has an unknown escape \\") +
                                    text[i]);
    }
  }
  throw std::invalid_argument("a station's name has no closing quote");
}

}  // namespace

std::string station_comment_lines(const std::vector<Station>& stations,
                                  const Eigen::Vector3d& shift, std::string_view prefix) {
  std::string lines;
  for (const Station& station : stations) {
    lines.append(prefix).append(kStationKeyword).append(" ");
    append_quoted(lines, station.name);
    const Eigen::Vector3d origin = station.frame.origin + shift;
    const Eigen::Quaterniond& q = station.frame.orientation;
    for (const double value : {origin.x(), origin.y(), origin.z(), q.w(), q.x(), q.y(), q.z()}) {
      lines += ' ';
      append_number(lines, value);
    }
    lines += ' ';
    append_number(lines, static_cast<unsigned long long>(station.frame.width));
    lines += ' ';
    append_number(lines, static_cast<unsigned long long>(station.frame.height));
    lines += '\n';
  }
  return lines;
}

std::optional<Station> parse_station_comment(std::string_view text) {
  Tokens first(text);
  if (first.next() != kStationKeyword) return std::nullopt;
  std::string_view rest = first.rest();
  Station station;
  station.name = take_quoted(rest);
  Tokens tokens(rest);
  double pose[7];
  for (double& value : pose) {
    const std::string_view token = tokens.next();
    if (!parse_double(token, value) || !std::isfinite(value)) {
      throw std::invalid_argument("station '" + station.name + "': " + quoted(token) +
                                  " is no finite number (expected ox oy oz qw qx qy qz width "
                                  "height)");
    }
  }
  std::int64_t grid[2];
  for (std::int64_t& value : grid) {
    const std::string_view token = tokens.next();
    if (!parse_whole_number(token, value) || value < 0 || value > (std::int64_t{1} << 32)) {
      throw std::invalid_argument("station '" + station.name + "': grid size " + quoted(token) +
                                  " is no whole number from 0 to 2^32");
    }
  }
  if (!tokens.next().empty()) {
    throw std::invalid_argument("station '" + station.name +
                                "': more than ox oy oz qw qx qy qz "
                                "width height");
  }
  const Eigen::Quaterniond q(pose[3], pose[4], pose[5], pose[6]);
  if (std::abs(q.norm() - 1.0) > 1e-3) {
    throw std::invalid_argument("station '" + station.name +
                                "': its orientation is no unit quaternion (norm " +
                                std::to_string(q.norm()) + ")");
  }
  station.frame.origin = Eigen::Vector3d(pose[0], pose[1], pose[2]);
  station.frame.orientation = q.normalized();
  station.frame.width = static_cast<std::size_t>(grid[0]);
  station.frame.height = static_cast<std::size_t>(grid[1]);
  return station;
}

std::optional<ClassComment> parse_class_comment(std::string_view text) {
  Tokens tokens(text);
  if (tokens.next() != "class") return std::nullopt;
  ClassComment comment;
  if (!parse_whole_number(tokens.next(), comment.id)) return std::nullopt;
  comment.name = std::string(tokens.rest());  // may be empty; inner spaces kept
  return comment;
}

void ClassNameList::add(const ClassComment& comment, const std::string& path, std::size_t line) {
  constexpr std::int64_t kMaxClasses = 1 << 16;
  if (comment.id < 0 || comment.id >= kMaxClasses) {
    throw InputError(path, line,
                     "class id " + std::to_string(comment.id) + " is outside 0.." +
                         std::to_string(kMaxClasses - 1));
  }
  const auto id = static_cast<std::size_t>(comment.id);
  if (id >= names_.size()) {
    names_.resize(id + 1);
    lines_.resize(id + 1, 0);
  }
  if (lines_[id] != 0) {
    throw InputError(path, line,
                     "class id " + std::to_string(id) + " is named twice (first on line " +
                         std::to_string(lines_[id]) + ")");
  }
  names_[id] = comment.name;
  lines_[id] = line;
}

std::vector<std::string> ClassNameList::finish(const std::string& path) const {
  for (std::size_t id = 0; id < lines_.size(); ++id) {
    if (lines_[id] == 0) {
      throw InputError(path, 0,
                       "class comments name ids up to " + std::to_string(lines_.size() - 1) +
                           " but not " + std::to_string(id));
    }
  }
  return names_;
}

std::string class_comment_lines(const std::vector<std::string>& names, std::string_view prefix) {
  std::string lines;
  for (std::size_t id = 0; id < names.size(); ++id) {
    std::string name = names[id];
    // A header comment ends at the end of the line, so a name must not contain one.
    for (char& c : name) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    lines.append(prefix).append("class ").append(std::to_string(id)).append(" ");
    lines.append(name).append("\n");
  }
  return lines;
}

std::string id_problem(std::int64_t id, bool is_label, std::size_t class_count) {
  const char* what = is_label ? "label " : "instance ";
  if (id < -1) {
    return what + std::to_string(id) + " is negative (only -1, meaning none, is allowed)";
  }
  if (id > std::numeric_limits<std::int32_t>::max()) {
    return what + std::to_string(id) + " does not fit in 32 bits";
  }
  if (is_label && class_count > 0 && id >= static_cast<std::int64_t>(class_count)) {
    return what + std::to_string(id) + " has no class name (the header names " +
           std::to_string(class_count) + " classes)";
  }
  return "";
}

namespace {

bool is_identifier(const std::string& name) {
  if (name.empty() || (name[0] >= '0' && name[0] <= '9')) return false;
  for (const char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

bool is_reserved_name(std::string_view name) {
  for (const char* reserved : {"x", "y", "z", "rgb", "rgba", "red", "green", "blue", "r", "g", "b",
                               "diffuse_red", "diffuse_green", "diffuse_blue"}) {
    if (name == reserved) return true;
  }
  return is_label_name(name) || is_instance_name(name) || is_intensity_name(name) ||
         name == kStationIdName;
}

void check_extra_fields(const PointCloud& cloud, const std::vector<ScalarField>& extra) {
  std::unordered_set<std::string> used;
  for (const ScalarField& field : extra) {
    if (!is_identifier(field.name)) {
      throw std::invalid_argument("write_cloud: field name '" + field.name +
                                  "' must be letters, digits and '_', not starting with a digit");
    }
    if (is_reserved_name(field.name) || !used.insert(field.name).second) {
      throw std::invalid_argument("write_cloud: field name '" + field.name + "' is already used");
    }
    if (field.values.size() != cloud.size()) {
      throw std::invalid_argument("write_cloud: field '" + field.name + "' has " +
                                  std::to_string(field.values.size()) + " values for " +
                                  std::to_string(cloud.size()) + " points");
    }
    if (!field.integer) continue;
    for (std::size_t i = 0; i < field.values.size(); ++i) {
      const float value = field.values[i];
      // 2^31 is exactly representable as a float; anything below it in
      // magnitude that is whole fits in an int32.
      const bool whole = std::isfinite(value) && value == std::floor(value) &&
                         value >= -2147483648.0f && value < 2147483648.0f;
      if (!whole) {
        throw std::invalid_argument("write_cloud: integer field '" + field.name + "' has value " +
                                    std::to_string(value) + " at point " + std::to_string(i) +
                                    ", not a whole 32-bit number");
      }
    }
  }
}

}  // namespace occlusion::detail
