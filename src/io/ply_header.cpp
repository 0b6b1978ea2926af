#include "ply_header.hpp"

#include <algorithm>
#include <stdexcept>

#include "cloud_formats.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {

std::optional<PlyType> parse_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::kInt8;
  if (name == "uchar" || name == "uint8") return PlyType::kUint8;
  if (name == "short" || name == "int16") return PlyType::kInt16;
  if (name == "ushort" || name == "uint16") return PlyType::kUint16;
  if (name == "int" || name == "int32") return PlyType::kInt32;
  if (name == "uint" || name == "uint32") return PlyType::kUint32;
  if (name == "float" || name == "float32") return PlyType::kFloat32;
  if (name == "double" || name == "float64") return PlyType::kFloat64;
  return std::nullopt;
}

std::size_t type_size(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 0;
}

bool is_integer(PlyType type) {
  return type != PlyType::kFloat32 && type != PlyType::kFloat64;
}

void integer_range(PlyType type, double& lo, double& hi) {
  switch (type) {
    case PlyType::kInt8:
      lo = -128, hi = 127;
      return;
    case PlyType::kUint8:
      lo = 0, hi = 255;
      return;
    case PlyType::kInt16:
      lo = -32768, hi = 32767;
      return;
    case PlyType::kUint16:
      lo = 0, hi = 65535;
      return;
    case PlyType::kInt32:
      lo = -2147483648.0, hi = 2147483647.0;
      return;
    default:
      lo = 0, hi = 4294967295.0;
  }
}

namespace {

std::optional<Station> station_comment(std::string_view text, const std::string& path,
                                       std::size_t line) {
  try {
    return parse_station_comment(text);
  } catch (const std::invalid_argument& e) {
    throw InputError(path, line, e.what());
  }
}

}  // namespace

PlyHeader parse_header(std::string_view bytes, const std::string& path) {
  PlyHeader header;
  ClassNameList class_names;
  bool have_format = false;
  bool ended = false;
  Lines lines(bytes, 1, LineEnds::kLfOnly);  // counts bytes to the body
  std::string_view line;
  std::size_t consumed = 0;
  while (!ended && lines.next(line)) {
    consumed += line.size() + 1;
    const std::size_t number = lines.number();
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    Tokens tokens(line);
    const std::string_view keyword = tokens.next();
    if (number == 1) {
      if (keyword != "ply" || !tokens.next().empty()) {
        throw InputError(path, 1, "not a PLY file (the first line is not 'ply')");
      }
      continue;
    }
    if (keyword == "format") {
      const std::string_view name = tokens.next();
      if (name == "ascii") {
        header.encoding = PlyEncoding::kAscii;
      } else if (name == "binary_little_endian") {
        header.encoding = PlyEncoding::kLittleEndian;
      } else if (name == "binary_big_endian") {
        header.encoding = PlyEncoding::kBigEndian;
      } else {
        throw InputError(path, number, "unknown PLY format " + quoted(name));
      }
      have_format = true;
    } else if (keyword == "comment") {
      if (const auto comment = parse_class_comment(tokens.rest())) {
        class_names.add(*comment, path, number);
      } else if (const auto station = station_comment(tokens.rest(), path, number)) {
        header.stations.push_back(*station);
      } else {
        header.comments.emplace_back(tokens.rest());
      }
    } else if (keyword == "obj_info" || keyword.empty()) {
      continue;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(tokens.next());
      std::int64_t count = -1;
      if (element.name.empty() || !parse_whole_number(tokens.next(), count) || count < 0) {
        throw InputError(path, number, "element line is not 'element <name> <count>'");
      }
      element.count = static_cast<std::size_t>(count);
      element.line = number;
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) {
        throw InputError(path, number, "property before any element");
      }
      PlyProperty property;
      std::string_view type_name = tokens.next();
      if (type_name == "list") {
        property.is_list = true;
        const std::string_view count_name = tokens.next();
        const auto count_type = parse_type(count_name);
        if (!count_type || !is_integer(*count_type)) {
          throw InputError(path, number,
                           "list count type " + quoted(count_name) + " is not an integer type");
        }
        property.count_type = *count_type;
        type_name = tokens.next();
      }
      const auto type = parse_type(type_name);
      if (!type) throw InputError(path, number, "unknown property type " + quoted(type_name));
      property.type = *type;
      property.name = std::string(tokens.next());
      if (property.name.empty()) throw InputError(path, number, "property has no name");
      header.elements.back().properties.push_back(std::move(property));
    } else if (keyword == "end_header") {
      ended = true;
      header.body_offset = std::min(consumed, bytes.size());  // no newline at the very end
      header.body_line = number + 1;
    } else {
      throw InputError(path, number, "unknown PLY header line starting " + quoted(keyword));
    }
  }
  if (!ended) throw InputError(path, 0, "the header has no end_header line");
  if (!have_format) throw InputError(path, 0, "the header has no format line");
  header.class_names = class_names.finish(path);
  return header;
}

}  // namespace occlusion::detail
