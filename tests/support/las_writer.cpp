#include "support/las_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace occlusion::testing {
namespace {

// Each format's record size and where its colour starts (0: none), from the
// LAS 1.4 R15 tables 7-16, written out again here rather than shared with the
// reader.
constexpr std::size_t kRecordSize[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
constexpr std::size_t kColourAt[] = {0, 0, 20, 28, 0, 28, 0, 30, 30, 0, 30};

void put(std::string& bytes, std::size_t at, std::uint64_t value, int size) {
  for (int k = 0; k < size; ++k) bytes[at + k] = static_cast<char>((value >> (8 * k)) & 0xFF);
}

void put_double(std::string& bytes, std::size_t at, double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  put(bytes, at, bits, 8);
}

}  // namespace

std::string las_bytes(const LasTestFile& file) {
  const std::size_t header_size = file.version_minor >= 4   ? 375
                                  : file.version_minor == 3 ? 235
                                                            : 227;
  const std::size_t vlr_size = file.laszip_vlr ? 54 + 34 : 0;
  const std::size_t record = kRecordSize[file.point_format] + file.extra_bytes;
  const std::size_t point_offset = header_size + vlr_size;
  std::string bytes(point_offset + record * file.points.size(), '\0');

  std::memcpy(bytes.data(), "LASF", 4);
  bytes[24] = 1;
  bytes[25] = static_cast<char>(file.version_minor);
  std::memcpy(bytes.data() + 26, "occlusion tests", 15);
  put(bytes, 94, header_size, 2);
  put(bytes, 96, point_offset, 4);
  put(bytes, 100, file.laszip_vlr ? 1 : 0, 4);
  bytes[104] = static_cast<char>(file.point_format);
  put(bytes, 105, record, 2);
  const std::uint64_t count = file.points.size();
  put(bytes, 107, file.point_format >= 6 ? 0 : count, 4);
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
    put_double(bytes, 131 + 8 * a, file.scale[a]);
    put_double(bytes, 155 + 8 * a, file.offset[a]);
  }
  for (const LasTestPoint& p : file.points) {
    const double v[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], v[a]);
      hi[a] = std::max(hi[a], v[a]);
    }
  }
  for (int a = 0; a < 3 && !file.points.empty(); ++a) {
    put_double(bytes, 179 + 16 * a, hi[a]);
    put_double(bytes, 187 + 16 * a, lo[a]);
  }
  if (file.version_minor >= 4) put(bytes, 247, count, 8);
  if (file.laszip_vlr) {
    std::memcpy(bytes.data() + header_size + 2, "laszip encoded", 14);
    put(bytes, header_size + 18, 22204, 2);
    put(bytes, header_size + 20, 34, 2);
  }

  for (std::size_t i = 0; i < file.points.size(); ++i) {
    const LasTestPoint& p = file.points[i];
    const std::size_t at = point_offset + i * record;
    const double v[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) {
      const auto stored =
          static_cast<std::int64_t>(std::llround((v[a] - file.offset[a]) / file.scale[a]));
      put(bytes, at + 4 * a, static_cast<std::uint32_t>(static_cast<std::int32_t>(stored)), 4);
    }
    put(bytes, at + 12, p.intensity, 2);
    if (file.point_format >= 6) {
      bytes[at + 14] = 0x11;  // return 1 of 1
      bytes[at + 16] = static_cast<char>(p.classification);
    } else {
      bytes[at + 14] = 0x09;  // return 1 of 1
      const unsigned flags = file.set_class_flags ? 0xE0u : 0u;
      bytes[at + 15] = static_cast<char>((p.classification & 0x1Fu) | flags);
    }
    if (kColourAt[file.point_format] != 0) {
      for (int c = 0; c < 3; ++c)
        put(bytes, at + kColourAt[file.point_format] + 2 * c, p.rgb[c], 2);
    }
    for (std::size_t k = 0; k < file.extra_bytes; ++k) {
      bytes[at + kRecordSize[file.point_format] + k] = static_cast<char>(0xA5);
    }
  }
  return bytes;
}

}  // namespace occlusion::testing
