#pragma once
// A small E57 writer for the tests (not part of the tool): files with known
// points, poses, field types and bit widths, packet layouts, and deliberate
// faults, so the reader can be held to exact answers. It shares no code with
// the reader (its own CRC-32C and bit packing).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace occlusion::test {

struct E57FieldSpec {
  enum class Kind { kInteger, kScaledInteger, kSingle, kDouble };
  std::string name;
  Kind kind = Kind::kDouble;
  std::int64_t minimum = 0, maximum = 0;  // the integer kinds
  double scale = 1.0, offset = 0.0;       // ScaledInteger
  std::vector<std::int64_t> raw;          // the integer kinds: the stored integers
  std::vector<double> values;             // Float kinds
};

E57FieldSpec e57_double(std::string name, std::vector<double> values);
E57FieldSpec e57_single(std::string name, std::vector<double> values);
E57FieldSpec e57_integer(std::string name, std::int64_t minimum, std::int64_t maximum,
                         std::vector<std::int64_t> raw);
E57FieldSpec e57_scaled(std::string name, std::int64_t minimum, std::int64_t maximum, double scale,
                        double offset, std::vector<std::int64_t> raw);

struct E57ScanSpec {
  std::string name, guid;  // left out of the XML when empty
  std::optional<Eigen::Quaterniond> rotation;
  std::optional<Eigen::Vector3d> translation;
  std::vector<E57FieldSpec> fields;
  std::string extra_xml;        // more children of the scan (colorLimits, indexBounds...)
  std::string codecs_xml;       // children of points/codecs
  std::size_t packets = 1;      // data packets each bytestream is split over (unevenly)
  bool filler_packets = false;  // an empty and an index packet before the data
  std::optional<std::uint64_t> record_count;  // default: the fields' value count
};

struct E57FileSpec {
  std::vector<E57ScanSpec> scans;
  std::string images2d_xml;  // children of images2D
};

// The file's bytes: header, sections, XML, every page with its checksum.
std::string e57_bytes(const E57FileSpec& spec);
void write_e57(const std::string& path, const E57FileSpec& spec);

// Recomputes every page's checksum, after a test has changed bytes.
void fix_e57_checksums(std::string& bytes);

}  // namespace occlusion::test
