#pragma once
// The public header block of an ASPRS LAS file (versions 1.0 to 1.4, point
// data record formats 0 to 10), read and checked against the file's size
// before anything is allocated for its points.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace occlusion::detail {

struct LasHeader {
  int version_minor = 0;          // LAS 1.<minor>
  int point_format = 0;           // 0..10
  std::size_t record_length = 0;  // bytes per point, at least the format's own
  std::uint64_t point_count = 0;
  std::uint64_t point_offset = 0;  // byte where the point records start
  double scale[3] = {1, 1, 1};
  double offset[3] = {0, 0, 0};
};

// The bytes a point record of `format` (0..10) holds before any extra bytes.
std::size_t las_record_size(int format);
// Where a format's red, green, blue start in its record, or 0 if it has none.
std::size_t las_colour_offset(int format);

// Throws InputError (file `path`, the byte offset of the field at fault, and
// the reason) for a file that is not LAS, a version or point format this
// reader does not know, sizes that contradict each other or the file, or a
// LASzip-compressed file (LAZ: the message says how to decompress it).
LasHeader read_las_header(const std::string& path, std::string_view bytes);

}  // namespace occlusion::detail
