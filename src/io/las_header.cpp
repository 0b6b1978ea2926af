#include "las_header.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>

#include "little_endian.hpp"
#include "number_text.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/shell_quote.hpp"

namespace occlusion::detail {
namespace {

// Byte offsets of the public header block's fields (LAS 1.4 R15, table 3;
// the same places in every version, 1.3 and 1.4 adding fields at the end).
constexpr std::size_t kVersionMajorAt = 24;
constexpr std::size_t kVersionMinorAt = 25;
constexpr std::size_t kHeaderSizeAt = 94;
constexpr std::size_t kPointOffsetAt = 96;
constexpr std::size_t kVlrCountAt = 100;
constexpr std::size_t kPointFormatAt = 104;
constexpr std::size_t kRecordLengthAt = 105;
constexpr std::size_t kLegacyCountAt = 107;
constexpr std::size_t kScaleAt = 131;
constexpr std::size_t kOffsetAt = 155;
constexpr std::size_t kMaxAt = 179;  // max x, then min x, max y, min y, max z, min z
constexpr std::size_t kMinAt = 187;
constexpr std::size_t kCountAt = 247;  // LAS 1.4: the 64-bit point count
// The header's size in each version: 1.0 to 1.2, 1.3 (waveform start), 1.4.
constexpr std::size_t kHeaderSize12 = 227;
constexpr std::size_t kHeaderSize13 = 235;
constexpr std::size_t kHeaderSize14 = 375;
constexpr std::size_t kVlrHeaderSize = 54;
// The steps a 32-bit integer coordinate spans (2^32), and one for rounding.
constexpr double kInt32Steps = 4294967296.0 + 1.0;

std::string at_byte(std::size_t offset) {
  return "byte " + std::to_string(offset) + ": ";
}

std::string six_digits(double value) {
  std::string text;
  append_significant(text, value, 6);
  return text;
}

// Walks the VLRs from the header's end: InputError when they run into the
// points (the offset to the points lies inside them, so the first records
// would be read from VLR bytes); whether one is LASzip's ("laszip encoded"),
// by which, with bit 7 (and for some versions bit 6) of the point format,
// the LASzip compressor marks its files. Each VLR is at least 54 bytes, so
// a vast count stops at the points.
bool walk_vlrs(const std::string& path, std::string_view bytes, std::size_t header_size,
               std::uint32_t vlr_count, std::uint64_t point_offset) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::uint64_t at = header_size;
  bool laszip = false;
  for (std::uint32_t k = 0; k < vlr_count; ++k) {
    const std::uint64_t end = at + kVlrHeaderSize > point_offset
                                  ? at + kVlrHeaderSize
                                  : at + kVlrHeaderSize + le_u16(data + at + 20);
    if (end > point_offset) {
      throw InputError(path, 0,
                       at_byte(kPointOffsetAt) + "the points are said to start at byte " +
                           std::to_string(point_offset) + ", inside the header's " +
                           std::to_string(vlr_count) + " VLRs (byte " +
                           std::to_string(kVlrCountAt) + "): VLR " + std::to_string(k) +
                           " runs from byte " + std::to_string(at) + " to " + std::to_string(end));
    }
    laszip = laszip || std::memcmp(data + at + 2, "laszip encoded", 14) == 0;
    at = end;
  }
  return laszip;
}

// A name for the decompressed file beside `path`: X.las, else
// X-decompressed.las, X-decompressed-2.las, ...; never the input (a LAZ file
// named .las) nor a file that exists, so pasting the advice loses nothing.
std::string decompressed_name(const std::string& path) {
  const std::filesystem::path input(path);
  std::filesystem::path name = std::filesystem::path(input).replace_extension(".las");
  const std::filesystem::path stem = input.parent_path() / input.stem();
  std::error_code status;
  for (int k = 1; name == input || std::filesystem::exists(name, status); ++k) {
    name = stem.string() + "-decompressed" + (k == 1 ? "" : "-" + std::to_string(k)) + ".las";
  }
  return name.string();
}

// A file name as a tool's argument: quoted for the shell, and after ./ when
// it starts with - so that no tool takes it for an option.
std::string argument(const std::string& path) {
  return shell_quote(path.rfind('-', 0) == 0 ? "./" + path : path);
}

[[noreturn]] void refuse_laz(const std::string& path) {
  const std::string in = argument(path);
  const std::string out = argument(decompressed_name(path));
  throw InputError(
      path, 0,
      "the points are LASzip-compressed (LAZ); this build reads uncompressed LAS only, and "
      "Debian 12 packages no LAZ decompressor. Decompress it first, then give the .las: with "
      "PDAL, `pdal translate " +
          in + " " + out + "`; with LAStools, `laszip -i " + in + " -o " + out +
          "`; or with Python, `pip install 'laspy[lazrs]'` then `python3 -c 'import sys, laspy; "
          "laspy.read(sys.argv[1]).write(sys.argv[2])' " +
          in + " " + out + "`");
}

}  // namespace

std::size_t las_record_size(int format) {
  static constexpr std::size_t kSizes[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  return kSizes[format];
}

std::size_t las_colour_offset(int format) {
  static constexpr std::size_t kOffsets[] = {0, 0, 20, 28, 0, 28, 0, 30, 30, 0, 30};
  return kOffsets[format];
}

LasHeader read_las_header(const std::string& path, std::string_view bytes) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < 4 || bytes.substr(0, 4) != "LASF") {
    throw InputError(path, 0, at_byte(0) + "not a LAS file (it does not start with \"LASF\")");
  }
  if (bytes.size() < kHeaderSize12) {
    throw InputError(path, 0,
                     "truncated: the file ends at byte " + std::to_string(bytes.size()) +
                         ", inside the " + std::to_string(kHeaderSize12) + "-byte LAS header");
  }
  LasHeader header;
  const int major = data[kVersionMajorAt];
  header.version_minor = data[kVersionMinorAt];
  if (major != 1 || header.version_minor > 4) {
    throw InputError(path, 0,
                     at_byte(kVersionMajorAt) + "LAS version " + std::to_string(major) + "." +
                         std::to_string(header.version_minor) +
                         "; this reader knows LAS 1.0 to 1.4");
  }
  const std::size_t needed = header.version_minor >= 4   ? kHeaderSize14
                             : header.version_minor == 3 ? kHeaderSize13
                                                         : kHeaderSize12;
  const std::size_t header_size = le_u16(data + kHeaderSizeAt);
  if (header_size < needed) {
    throw InputError(path, 0,
                     at_byte(kHeaderSizeAt) + "header size " + std::to_string(header_size) +
                         " is less than the " + std::to_string(needed) + " bytes of a LAS 1." +
                         std::to_string(header.version_minor) + " header");
  }
  if (header_size > bytes.size()) {
    throw InputError(path, 0,
                     at_byte(kHeaderSizeAt) + "header size " + std::to_string(header_size) +
                         " is more than the file's " + std::to_string(bytes.size()) + " bytes");
  }
  header.point_offset = le_u32(data + kPointOffsetAt);
  if (header.point_offset < header_size || header.point_offset > bytes.size()) {
    throw InputError(path, 0,
                     at_byte(kPointOffsetAt) + "the points are said to start at byte " +
                         std::to_string(header.point_offset) + ", outside bytes " +
                         std::to_string(header_size) + ".." + std::to_string(bytes.size()) +
                         " (after the header, inside the file)");
  }
  const int raw_format = data[kPointFormatAt];
  if ((raw_format & 0xC0) != 0 ||
      walk_vlrs(path, bytes, header_size, le_u32(data + kVlrCountAt), header.point_offset)) {
    refuse_laz(path);
  }
  if (raw_format > 10) {
    throw InputError(path, 0,
                     at_byte(kPointFormatAt) + "point data record format " +
                         std::to_string(raw_format) + "; LAS 1.4 defines formats 0 to 10");
  }
  header.point_format = raw_format;
  header.record_length = le_u16(data + kRecordLengthAt);
  const std::size_t minimum = las_record_size(raw_format);
  if (header.record_length < minimum) {
    throw InputError(path, 0,
                     at_byte(kRecordLengthAt) + "point records of " +
                         std::to_string(header.record_length) + " bytes, fewer than the " +
                         std::to_string(minimum) + " of point format " +
                         std::to_string(raw_format));
  }
  const std::uint64_t legacy_count = le_u32(data + kLegacyCountAt);
  header.point_count = legacy_count;
  if (header.version_minor >= 4) {
    // LAS 1.4 keeps the 32-bit count for older readers (0 when it cannot
    // hold the count, and always 0 for formats 6 to 10).
    const std::uint64_t count = le_u64(data + kCountAt);
    if (count != 0 && legacy_count != 0 && count != legacy_count) {
      throw InputError(path, 0,
                       at_byte(kCountAt) + "the point count " + std::to_string(count) +
                           " differs from the legacy point count " + std::to_string(legacy_count) +
                           " at byte " + std::to_string(kLegacyCountAt));
    }
    if (count != 0) header.point_count = count;
  }
  // Waveform packets (1.3) and extended VLRs (1.4) may follow the points.
  const std::uint64_t available = (bytes.size() - header.point_offset) / header.record_length;
  if (header.point_count > available) {
    throw InputError(path, 0,
                     "truncated: the header declares " + std::to_string(header.point_count) +
                         " points of " + std::to_string(header.record_length) +
                         " bytes from byte " + std::to_string(header.point_offset) +
                         ", but the file ends at byte " + std::to_string(bytes.size()) +
                         " (room for " + std::to_string(available) + ")");
  }
  for (int axis = 0; axis < 3; ++axis) {
    header.scale[axis] = le_f64(data + kScaleAt + 8 * axis);
    header.offset[axis] = le_f64(data + kOffsetAt + 8 * axis);
    if (!std::isfinite(header.scale[axis]) || header.scale[axis] == 0.0) {
      throw InputError(path, 0,
                       at_byte(kScaleAt + 8 * axis) + std::string(1, char('x' + axis)) +
                           " scale factor is zero or not finite");
    }
    // A scale too small for the data collapses the axis (at 1e-308 every
    // coordinate lies within 1e-298 of the offset): 2^32 steps of it must
    // span the header's bounds. (Bounds left 0 span nothing.)
    const double span =
        std::fabs(le_f64(data + kMaxAt + 16 * axis) - le_f64(data + kMinAt + 16 * axis));
    if (std::isfinite(span) && !(span / std::fabs(header.scale[axis]) <= kInt32Steps)) {
      throw InputError(path, 0,
                       at_byte(kScaleAt + 8 * axis) + std::string(1, char('x' + axis)) +
                           " scale factor " + six_digits(header.scale[axis]) +
                           " is too small for the data: the header's bounds (bytes " +
                           std::to_string(kMaxAt + 16 * axis) + ", " +
                           std::to_string(kMinAt + 16 * axis) + ") span " + six_digits(span) +
                           ", and 32-bit integers at that scale span at most " +
                           six_digits(std::fabs(header.scale[axis]) * kInt32Steps));
    }
    // Every stored integer must give a finite coordinate.
    if (!std::isfinite(std::fabs(header.scale[axis]) * 2147483648.0 +
                       std::fabs(header.offset[axis]))) {
      throw InputError(path, 0,
                       at_byte(kOffsetAt + 8 * axis) + std::string(1, char('x' + axis)) +
                           " offset is not finite, or with the scale factor gives coordinates "
                           "beyond double's range");
    }
  }
  return header;
}

}  // namespace occlusion::detail
