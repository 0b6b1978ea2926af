#pragma once
// The PLY header: format, elements and their properties, the class names
// in `comment class <id> <name>` lines and the stations in `comment station`
// lines (cloud_formats.hpp). The body is read by ply_cloud_reader.cpp.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion::detail {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

std::optional<PlyType> parse_type(std::string_view name);
std::size_t type_size(PlyType type);
bool is_integer(PlyType type);
// The range of an integer type, to reject an ascii `300` for a uchar.
void integer_range(PlyType type, double& lo, double& hi);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::size_t line = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { kAscii, kLittleEndian, kBigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::kAscii;
  std::vector<PlyElement> elements;
  std::vector<std::string> class_names;
  std::vector<Station> stations;      // origins in the file's frame
  std::vector<std::string> comments;  // the text of every other `comment` line, in order
  std::size_t body_offset = 0;        // first byte after the end_header line
  std::size_t body_line = 0;          // line number of that byte (ascii)
};

// InputError, with the header line, for anything that is not a PLY header.
PlyHeader parse_header(std::string_view bytes, const std::string& path);

}  // namespace occlusion::detail
