#pragma once
// LAS files for the tests, written here from known points: every version
// (1.0-1.4) and point format (0-10), so the reader is held against values
// chosen by hand rather than against a second reader.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion::testing {

struct LasTestPoint {
  double x = 0, y = 0, z = 0;  // stored as round((v - offset) / scale)
  std::uint16_t intensity = 0;
  std::uint8_t classification = 0;     // formats 0-5: 0..31, written below the flags
  std::array<std::uint16_t, 3> rgb{};  // formats with colour only
};

struct LasTestFile {
  int version_minor = 2;
  int point_format = 3;
  std::size_t extra_bytes = 0;  // per record, after the format's own fields
  double scale[3] = {0.001, 0.001, 0.001};
  double offset[3] = {0, 0, 0};
  // Formats 0-5: the synthetic, key-point and withheld bits set above the
  // class, which the reader must mask off.
  bool set_class_flags = true;
  bool laszip_vlr = false;  // a "laszip encoded" VLR (no compressed data follows)
  std::vector<LasTestPoint> points;
};

// The file's bytes: the public header block of its version, the VLR if
// asked for, then the point records.
std::string las_bytes(const LasTestFile& file);

// Byte offsets of header fields the tests corrupt.
inline constexpr std::size_t kLasHeaderSizeAt = 94;
inline constexpr std::size_t kLasPointOffsetAt = 96;
inline constexpr std::size_t kLasVlrCountAt = 100;
inline constexpr std::size_t kLasPointFormatAt = 104;
inline constexpr std::size_t kLasRecordLengthAt = 105;
inline constexpr std::size_t kLasLegacyCountAt = 107;
inline constexpr std::size_t kLasScaleAt = 131;
inline constexpr std::size_t kLasCountAt = 247;

}  // namespace occlusion::testing
