#pragma once
// What the E57 XML section says about each data3D scan, as the reader needs
// it: the pose, the record layout (the prototype's fields, one bytestream
// each, in order), where the binary section is, and the limits that scale
// colour and intensity.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace occlusion::detail {

// One leaf of a scan's prototype: one value per record, one bytestream.
struct E57Field {
  enum class Kind { kInteger, kScaledInteger, kFloat };
  std::string name;  // the element's name, e.g. "cartesianX"
  Kind kind = Kind::kFloat;
  std::int64_t minimum = 0, maximum = 0;  // Integer and ScaledInteger: the raw range
  double scale = 1.0, offset = 0.0;       // ScaledInteger: value = raw * scale + offset
  bool single = false;                    // Float: precision="single"
  // Bits each record takes in the bytestream: ceil(log2(maximum - minimum + 1))
  // for the integer kinds (0 when minimum == maximum), 32 or 64 for Float.
  unsigned bits = 0;
};

struct E57Range {
  double minimum = 0, maximum = 0;
};

struct E57Scan {
  std::string element;  // "data3D/<k>", for errors
  std::string name;     // name, else guid, else "scan_<k>"
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  std::vector<E57Field> fields;      // bytestream order
  std::uint64_t section_offset = 0;  // physical offset of the CompressedVector section
  std::uint64_t record_count = 0;
  std::optional<E57Range> intensity_limits;
  std::optional<std::array<E57Range, 3>> colour_limits;  // red, green, blue
  // indexBounds: rowMinimum..rowMaximum, columnMinimum..columnMaximum.
  std::optional<E57Range> row_bounds, column_bounds;

  // The index of the field named `name`, or -1.
  int field(std::string_view field_name) const;
};

// The data3D scans of the XML section, in order. InputError naming `path`
// and the element for malformed XML, values that are not numbers, a pose
// whose rotation is not a unit quaternion, a prototype field of a type other
// than Integer, ScaledInteger or Float, a codec other than bitPackCodec, and
// a file with no data3D scan (saying so when it holds only images2D).
std::vector<E57Scan> parse_e57_xml(std::string_view xml, const std::string& path);

}  // namespace occlusion::detail
