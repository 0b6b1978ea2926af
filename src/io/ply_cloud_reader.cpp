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
#include "ply_header.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {
namespace {

// Where each vertex property goes in the cloud.
enum class Role { kX, kY, kZ, kRed, kGreen, kBlue, kLabel, kInstance, kExtra, kSkip };

Role role_of(const PlyProperty& property) {
  if (property.is_list) return Role::kSkip;
  const std::string& name = property.name;
  if (name == "x") return Role::kX;
  if (name == "y") return Role::kY;
  if (name == "z") return Role::kZ;
  if (name == "red" || name == "r" || name == "diffuse_red") return Role::kRed;
  if (name == "green" || name == "g" || name == "diffuse_green") return Role::kGreen;
  if (name == "blue" || name == "b" || name == "diffuse_blue") return Role::kBlue;
  if (is_label_name(name)) return Role::kLabel;
  if (is_instance_name(name)) return Role::kInstance;
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
    default:
      return "";
  }
}

class PlyCloudReader {
 public:
  PlyCloudReader(std::string_view bytes, const std::string& path, CloudReadReport& report)
      : bytes_(bytes), path_(path), report_(report) {}

  PointCloud run() {
    header_ = parse_header(bytes_, path_);
    assign_roles();
    cloud_.class_names = header_.class_names;
    if (header_.encoding == PlyEncoding::kAscii) {
      read_ascii_body();
    } else {
      read_binary_body();
    }
    for (std::size_t f = 0; f < extra_.size(); ++f) {
      report_.extra_fields.push_back(std::move(extra_[f]));
    }
    return std::move(cloud_);
  }

 private:
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
      const Role role = role_of(property);
      roles_.push_back(role);
      extra_index_.push_back(kNone);
      if (role == Role::kExtra) {
        extra_index_.back() = extra_.size();
        extra_.push_back({property.name, {}, is_integer(property.type)});
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
      if (colour && !is_integer(property.type)) {
        throw InputError(path_, vertex.line,
                         "colour property '" + property.name +
                             "' is floating point; only integer colours 0..255 are read");
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
    has_labels_ = seen[static_cast<int>(Role::kLabel)];
    has_instances_ = seen[static_cast<int>(Role::kInstance)];

    // Capped by the file size, so a header that claims billions of vertices
    // fails as truncated instead of exhausting memory first.
    const std::size_t reserve = std::min(vertex.count, bytes_.size() / 4);
    cloud_.positions.reserve(reserve);
    if (has_colours_) cloud_.colours.reserve(reserve);
    if (has_labels_) cloud_.labels.reserve(reserve);
    if (has_instances_) cloud_.instances.reserve(reserve);
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
    const Eigen::Vector3f position(static_cast<float>(xyz_[0]), static_cast<float>(xyz_[1]),
                                   static_cast<float>(xyz_[2]));
    if (!position.allFinite()) {
      ++report_.dropped_nan;
      return;
    }
    cloud_.positions.push_back(position);
    if (has_colours_) cloud_.colours.push_back(rgb_);
    if (has_labels_) cloud_.labels.push_back(label_);
    if (has_instances_) cloud_.instances.push_back(instance_);
    for (std::size_t f = 0; f < extra_.size(); ++f) extra_[f].values.push_back(extra_values_[f]);
  }

  // --- ascii: one element instance per line -------------------------------

  void read_ascii_body() {
    extra_values_.assign(extra_.size(), 0.0f);
    Lines lines(bytes_.substr(header_.body_offset), header_.body_line);
    std::string_view line;
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      const PlyElement& element = header_.elements[e];
      for (std::size_t i = 0; i < element.count; ++i) {
        do {
          if (!lines.next(line)) {
            throw InputError(path_, lines.number(),
                             "the file ends after " + std::to_string(i) + " of the " +
                                 std::to_string(element.count) + " " + element.name +
                                 " lines the header declares");
          }
        } while (is_blank_line(line));
        read_ascii_instance(element, e == vertex_element_, line, lines.number());
      }
    }
    while (lines.next(line)) {
      if (!is_blank_line(line)) {
        throw InputError(path_, lines.number(),
                         "data after the last element (the header declares " + counts_text() + ")");
      }
    }
  }

  void read_ascii_instance(const PlyElement& element, bool is_vertex, std::string_view line,
                           std::size_t number) {
    Tokens tokens(line);
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      std::size_t items = 1;
      if (property.is_list) {
        const double count = ascii_value(tokens, property.count_type, element, property, number);
        if (count < 0) throw InputError(path_, number, "negative list length");
        items = static_cast<std::size_t>(count);
      }
      for (std::size_t k = 0; k < items; ++k) {
        const double value = ascii_value(tokens, property.type, element, property, number);
        if (is_vertex && !property.is_list) {
          const std::string problem = take(p, value);
          if (!problem.empty()) throw InputError(path_, number, problem);
        }
      }
    }
    if (!tokens.next().empty()) {
      throw InputError(path_, number,
                       "more values than the " + element.name + " element's " +
                           std::to_string(element.properties.size()) + " properties");
    }
    if (is_vertex) commit_vertex();
  }

  double ascii_value(Tokens& tokens, PlyType type, const PlyElement& element,
                     const PlyProperty& property, std::size_t number) {
    const std::string_view token = tokens.next();
    if (token.empty()) {
      throw InputError(
          path_, number,
          "the line ends before " + element.name + " property '" + property.name + "'");
    }
    double value = 0;
    if (is_integer(type)) {
      std::int64_t whole = 0;
      double lo = 0;
      double hi = 0;
      integer_range(type, lo, hi);
      if (!parse_whole_number(token, whole) || static_cast<double>(whole) < lo ||
          static_cast<double>(whole) > hi) {
        throw InputError(path_, number,
                         "property '" + property.name + "' value " + quoted(token) +
                             " is not an integer of its type");
      }
      value = static_cast<double>(whole);
    } else if (!parse_double(token, value)) {
      throw InputError(
          path_, number,
          "property '" + property.name + "' value " + quoted(token) + " is not a number");
    }
    return value;
  }

  // --- binary ------------------------------------------------------------

  void read_binary_body() {
    extra_values_.assign(extra_.size(), 0.0f);
    big_endian_ = header_.encoding == PlyEncoding::kBigEndian;
    std::size_t at = header_.body_offset;
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      const PlyElement& element = header_.elements[e];
      check_fits(element, at);
      if (e != vertex_element_ && fixed_size(element)) {
        at += element.count * record_size(element);
        continue;
      }
      for (std::size_t i = 0; i < element.count; ++i) {
        read_binary_instance(element, e == vertex_element_, i, at);
      }
    }
    if (at != bytes_.size()) {
      throw InputError(path_, 0,
                       std::to_string(bytes_.size() - at) +
                           " bytes after the end of the data at byte " + std::to_string(at) +
                           " (the header declares " + counts_text() + ")");
    }
  }

  static bool fixed_size(const PlyElement& element) {
    for (const PlyProperty& property : element.properties) {
      if (property.is_list) return false;
    }
    return true;
  }

  // Bytes of one instance, counting each list as empty: a lower bound.
  static std::size_t record_size(const PlyElement& element) {
    std::size_t size = 0;
    for (const PlyProperty& property : element.properties) {
      size += type_size(property.is_list ? property.count_type : property.type);
    }
    return size;
  }

  // Reports truncation before reading (or allocating for) an element whose
  // instances cannot all fit in what is left of the file.
  void check_fits(const PlyElement& element, std::size_t at) const {
    const std::size_t size = record_size(element);
    if (size == 0) return;
    const std::size_t left = bytes_.size() - at;
    if (element.count <= left / size) return;
    throw InputError(path_, 0,
                     "truncated: the file ends at byte " + std::to_string(bytes_.size()) +
                         ", after " + std::to_string(left / size) + " of the " +
                         std::to_string(element.count) + " " + element.name +
                         " records the header declares (" + std::to_string(size) +
                         " bytes each from byte " + std::to_string(at) + ")");
  }

  void read_binary_instance(const PlyElement& element, bool is_vertex, std::size_t index,
                            std::size_t& at) {
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (property.is_list) {
        const double count = binary_value(property.count_type, element, property, index, at);
        if (count < 0) {
          throw InputError(path_, 0,
                           "negative list length at byte " +
                               std::to_string(at - type_size(property.count_type)));
        }
        const std::size_t item = type_size(property.type);
        const auto items = static_cast<std::size_t>(count);
        if (items > (bytes_.size() - at) / item) truncated(element, property, index, at);
        at += items * item;
        continue;
      }
      const std::size_t start = at;
      const double value = binary_value(property.type, element, property, index, at);
      if (is_vertex) {
        const std::string problem = take(p, value);
        if (!problem.empty()) {
          throw InputError(path_, 0,
                           "at byte " + std::to_string(start) + " (vertex " +
                               std::to_string(index) + "): " + problem);
        }
      }
    }
    if (is_vertex) commit_vertex();
  }

  [[noreturn]] void truncated(const PlyElement& element, const PlyProperty& property,
                              std::size_t index, std::size_t at) const {
    throw InputError(path_, 0,
                     "truncated: the file ends at byte " + std::to_string(bytes_.size()) +
                         ", inside " + element.name + " " + std::to_string(index) + " of the " +
                         std::to_string(element.count) + " the header declares (property '" +
                         property.name + "' at byte " + std::to_string(at) + ")");
  }

  double binary_value(PlyType type, const PlyElement& element, const PlyProperty& property,
                      std::size_t index, std::size_t& at) const {
    const std::size_t size = type_size(type);
    if (size > bytes_.size() - at) truncated(element, property, index, at);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data() + at);
    at += size;
    // Assembling the bits by shifts reads either byte order on any host.
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const std::size_t shift = big_endian_ ? 8 * (size - 1 - k) : 8 * k;
      bits |= std::uint64_t{data[k]} << shift;
    }
    switch (type) {
      case PlyType::kInt8:
        return static_cast<std::int8_t>(bits);
      case PlyType::kUint8:
        return static_cast<double>(bits);
      case PlyType::kInt16:
        return static_cast<std::int16_t>(bits);
      case PlyType::kUint16:
        return static_cast<double>(bits);
      case PlyType::kInt32:
        return static_cast<std::int32_t>(bits);
      case PlyType::kUint32:
        return static_cast<double>(bits);
      case PlyType::kFloat32: {
        const auto narrow = static_cast<std::uint32_t>(bits);
        float value;
        std::memcpy(&value, &narrow, sizeof value);
        return value;
      }
      case PlyType::kFloat64: {
        double value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
      }
    }
    return 0;
  }

  std::string counts_text() const {
    std::string text;
    for (const PlyElement& element : header_.elements) {
      if (!text.empty()) text += ", ";
      text += std::to_string(element.count) + " " + element.name;
    }
    return text;
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
  bool has_labels_ = false;
  bool has_instances_ = false;
  bool big_endian_ = false;
  PointCloud cloud_;

  // The vertex being read, committed once all its properties are checked.
  double xyz_[3] = {0, 0, 0};
  std::array<std::uint8_t, 3> rgb_{};
  std::int32_t label_ = -1;
  std::int32_t instance_ = -1;
  std::vector<float> extra_values_;
};

}  // namespace

PointCloud read_ply(const std::string& path, CloudReadReport& report) {
  const std::string bytes = read_file_bytes(path);
  return PlyCloudReader(bytes, path, report).run();
}

}  // namespace occlusion::detail
