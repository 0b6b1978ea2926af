// LAS point records into a PointCloud: coordinates (integer x scale +
// offset, in double, then the global shift), intensity, colour and the
// classification as labels with the ASPRS class names.

#include <algorithm>
#include <array>

#include "cloud_formats.hpp"
#include "las_classes.hpp"
#include "las_header.hpp"
#include "little_endian.hpp"
#include "occlusion/io/file_bytes.hpp"

namespace occlusion::detail {
namespace {

constexpr std::size_t kIntensityAt = 12;
constexpr std::size_t kLegacyClassAt = 15;    // formats 0..5: 5-bit class, then 3 flags
constexpr std::size_t kExtendedClassAt = 16;  // formats 6..10: an 8-bit class
constexpr unsigned kLegacyClassMask = 0x1F;

// The LAS specification stores colour in 16 bits per channel (an 8-bit colour
// times 256), but many programs write 0..255 into those fields. As
// CloudCompare does, a file whose every channel value is at most 255 is
// taken as 8-bit, any other as 16-bit (its top 8 bits kept); a file whose
// colours are all 0 has none (the fields are there because the format has
// them). docs/formats.md says so.
enum class ColourDepth { kNone, kEight, kSixteen };

ColourDepth colour_depth(const unsigned char* points, const LasHeader& header) {
  const std::size_t at = las_colour_offset(header.point_format);
  if (at == 0) return ColourDepth::kNone;
  unsigned largest = 0;
  for (std::uint64_t i = 0; i < header.point_count; ++i) {
    const unsigned char* record = points + i * header.record_length + at;
    for (int c = 0; c < 3; ++c) largest = std::max<unsigned>(largest, le_u16(record + 2 * c));
  }
  if (largest == 0) return ColourDepth::kNone;
  return largest <= 255 ? ColourDepth::kEight : ColourDepth::kSixteen;
}

}  // namespace

PointCloud read_las(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& /*report*/) {
  const std::string bytes = read_file_bytes(path);
  const LasHeader header = read_las_header(path, bytes);
  const auto* points = reinterpret_cast<const unsigned char*>(bytes.data()) + header.point_offset;
  const std::size_t count = static_cast<std::size_t>(header.point_count);
  const ColourDepth depth = colour_depth(points, header);
  const std::size_t colour_at = las_colour_offset(header.point_format);
  const bool extended = header.point_format >= 6;

  PointCloud cloud;
  ShiftedPositions shifted(options);
  cloud.reserve_positions(count);
  cloud.intensities.reserve(count);
  cloud.labels.reserve(count);
  if (depth != ColourDepth::kNone) cloud.colours.reserve(count);
  int largest_class = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const unsigned char* record = points + i * header.record_length;
    double xyz[3];
    for (int axis = 0; axis < 3; ++axis) {
      xyz[axis] = le_i32(record + 4 * axis) * header.scale[axis] + header.offset[axis];
    }
    cloud.positions.push_back(shifted.local(xyz));
    cloud.intensities.push_back(static_cast<float>(le_u16(record + kIntensityAt)));
    const int label = extended ? record[kExtendedClassAt]
                               : static_cast<int>(record[kLegacyClassAt] & kLegacyClassMask);
    cloud.labels.push_back(label);
    largest_class = std::max(largest_class, label);
    if (depth != ColourDepth::kNone) {
      const int drop = depth == ColourDepth::kSixteen ? 8 : 0;
      std::array<std::uint8_t, 3> rgb{};
      for (int c = 0; c < 3; ++c) {
        rgb[c] = static_cast<std::uint8_t>(le_u16(record + colour_at + 2 * c) >> drop);
      }
      cloud.colours.push_back(rgb);
    }
  }
  for (int id = 0; count > 0 && id <= largest_class; ++id) {
    cloud.class_names.push_back(las_class_name(id, header.version_minor));
  }
  cloud.shift = shifted.checked_shift(path);
  return cloud;
}

}  // namespace occlusion::detail
