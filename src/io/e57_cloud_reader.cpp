// read_e57: every data3D scan of an E57 file into one cloud, each scan a
// station (its pose, name and grid) and each point tagged with its scan.

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cloud_formats.hpp"
#include "e57_bitpack.hpp"
#include "e57_pages.hpp"
#include "e57_scan.hpp"
#include "e57_section.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::detail {
namespace {

// Which prototype field holds what (-1: none).
struct Roles {
  int coordinate[3] = {-1, -1, -1};
  bool spherical = false;
  int invalid_state = -1;
  int colour[3] = {-1, -1, -1};
  int intensity = -1;
  int row = -1, column = -1;

  explicit Roles(const E57Scan& scan) {
    const char* const cartesian[3] = {"cartesianX", "cartesianY", "cartesianZ"};
    const char* const sphere[3] = {"sphericalRange", "sphericalAzimuth", "sphericalElevation"};
    const char* const colours[3] = {"colorRed", "colorGreen", "colorBlue"};
    int cartesian_found = 0, spherical_found = 0, colours_found = 0;
    for (int axis = 0; axis < 3; ++axis) {
      cartesian_found += scan.field(cartesian[axis]) >= 0;
      spherical_found += scan.field(sphere[axis]) >= 0;
      colours_found += scan.field(colours[axis]) >= 0;
    }
    spherical = cartesian_found < 3 && spherical_found == 3;
    for (int axis = 0; axis < 3; ++axis) {
      coordinate[axis] = scan.field(spherical ? sphere[axis] : cartesian[axis]);
      if (colours_found == 3) colour[axis] = scan.field(colours[axis]);
    }
    invalid_state = scan.field(spherical ? "sphericalInvalidState" : "cartesianInvalidState");
    intensity = scan.field("intensity");
    row = scan.field("rowIndex");
    column = scan.field("columnIndex");
  }

  bool has_coordinates() const {
    return coordinate[0] >= 0 && coordinate[1] >= 0 && coordinate[2] >= 0;
  }
  bool has_colours() const { return colour[0] >= 0; }
  bool has_grid() const { return row >= 0 && column >= 0; }
};

// The range a colour or intensity field's values span: the scan's limits
// when it gives them, else (colour) the integer field's own range.
std::optional<E57Range> field_range(const E57Field& field) {
  if (field.kind == E57Field::Kind::kFloat) return std::nullopt;
  const double a = static_cast<double>(field.minimum) * field.scale + field.offset;
  const double b = static_cast<double>(field.maximum) * field.scale + field.offset;
  return E57Range{std::min(a, b), std::max(a, b)};
}

class E57CloudReader {
 public:
  E57CloudReader(const std::string& path, const CloudReadOptions& options, CloudReadReport& report)
      : path_(path), report_(report), shifted_(options) {}

  PointCloud run() {
    const std::string bytes = read_file_bytes(path_);
    const E57Pages pages(bytes, path_);
    const E57Header& header = pages.header();
    const std::string xml =
        pages.read(pages.logical_of(header.xml_offset, "the XML section's offset"),
                   header.xml_length, "the XML section");
    const std::vector<E57Scan> scans = parse_e57_xml(xml, path_);
    bool colours = true, intensities = true;
    for (const E57Scan& scan : scans) {
      const Roles roles(scan);
      if (scan.record_count == 0) continue;
      colours = colours && roles.has_colours();
      intensities = intensities && roles.intensity >= 0;
    }
    for (std::size_t k = 0; k < scans.size(); ++k) {
      read_scan(pages, scans[k], static_cast<std::int32_t>(k), colours, intensities);
    }
    cloud_.shift = shifted_.checked_shift(path_);
    for (Station& station : cloud_.stations) station.frame.origin -= cloud_.shift;
    return std::move(cloud_);
  }

 private:
  // Each scan's points must have a section of their own: scans sharing bytes
  // would let a small file claim the same points over and over. The sections
  // kept do not overlap, so only the neighbours of a new one need checking
  // (a file may hold many thousands of scans).
  void claim(const E57Scan& scan, const E57Section& section) {
    const auto next = sections_.lower_bound(section.start);
    if (next != sections_.end() && next->first < section.end) {
      fail(scan, "its points' section overlaps that of " + next->second.second);
    }
    if (next != sections_.begin()) {
      const auto previous = std::prev(next);
      if (previous->second.first > section.start) {
        fail(scan, "its points' section overlaps that of " + previous->second.second);
      }
    }
    sections_.emplace(section.start, std::make_pair(section.end, scan.element));
  }

  [[noreturn]] void fail(const E57Scan& scan, const std::string& reason) const {
    throw InputError(path_, 0, "E57 scan " + scan.element + " ('" + scan.name + "'): " + reason);
  }

  E57Range checked_range(const E57Scan& scan, const std::optional<E57Range>& range,
                         const char* what) const {
    if (!range) fail(scan, std::string(what) + " is Float and the scan gives no limits for it");
    if (!(range->maximum > range->minimum)) {
      fail(scan, std::string(what) + " limits are empty (minimum == maximum)");
    }
    return *range;
  }

  // The grid's columns or rows: from indexBounds, else the largest index + 1.
  std::size_t grid_size(const E57Scan& scan, const std::optional<E57Range>& bounds,
                        std::int64_t largest, const char* what) const {
    const double size =
        bounds ? bounds->maximum - bounds->minimum + 1 : static_cast<double>(largest + 1);
    if (!(size >= 1 && size <= 4e9)) {
      fail(scan, std::string("its indexBounds give ") + std::to_string(size) + " " + what +
                     ", not 1..4e9");
    }
    return static_cast<std::size_t>(size);
  }

  // A bytestream holding more than its records need says the XML lies: a bit
  // width narrower than the values written (each read as a few of their low
  // bits: 0 or 1 for every point) or a recordCount below the records written
  // (the rest dropped). A writer pads each buffer it flushes to its register
  // word at most (libE57Format: 1, 2, 4 or 8 bytes by the width; a Float
  // none, a 0-bit field writes nothing), so more than that is refused.
  void refuse_surplus(const E57Scan& scan, const E57Field& field, const E57Stream& stream,
                      std::uint64_t needed_bits) const {
    const std::uint64_t surplus = stream.bytes - (needed_bits + 7) / 8;
    if (surplus == 0) return;
    const std::uint64_t word = field.kind == E57Field::Kind::kFloat ? 0
                               : field.bits == 0                    ? 0
                               : field.bits <= 8                    ? 1
                               : field.bits <= 16                   ? 2
                               : field.bits <= 32                   ? 4
                                                                    : 8;
    if (surplus < word * std::max<std::uint64_t>(stream.buffers, 1)) return;
    if (field.bits == 0) {
      fail(scan, field.name +
                     " takes 0 bits a record (its minimum equals its maximum) but its "
                     "bytestream holds " +
                     std::to_string(stream.bytes) +
                     " bytes: the values written are not the one value the prototype declares");
    }
    fail(scan, "its section holds " + std::to_string(stream.bytes) + " bytes of " + field.name +
                   ", room for " + std::to_string(stream.bytes * 8 / field.bits) +
                   " records of its " + std::to_string(field.bits) + " bits, but recordCount is " +
                   std::to_string(scan.record_count) + " (" +
                   std::to_string((needed_bits + 7) / 8) +
                   " bytes): a recordCount below the records written, or a bit width (minimum.."
                   "maximum) narrower than the values written, would drop or misread points");
  }

  void read_scan(const E57Pages& pages, const E57Scan& scan, std::int32_t index, bool colours,
                 bool intensities) {
    const Roles roles(scan);
    Station station;
    station.name = scan.name;
    station.frame.origin = scan.translation;  // made local once the shift is known
    station.frame.orientation = scan.rotation;
    if (scan.record_count == 0) {
      cloud_.stations.push_back(std::move(station));
      return;
    }
    if (!roles.has_coordinates()) {
      fail(scan, "its points have neither cartesianX/Y/Z nor sphericalRange/Azimuth/Elevation");
    }
    const E57Section section = read_compressed_vector(pages, scan.section_offset,
                                                      scan.fields.size(), scan.element + "/points");
    claim(scan, section);
    const std::vector<E57Stream>& streams = section.streams;
    // Every field read must hold its records' bits before anything is
    // allocated for them, so a record count cannot claim more than the file.
    std::vector<int> used;
    for (const int f : {roles.coordinate[0], roles.coordinate[1], roles.coordinate[2],
                        roles.invalid_state, roles.colour[0], roles.colour[1], roles.colour[2],
                        roles.intensity, roles.row, roles.column}) {
      if (f >= 0) used.push_back(f);
    }
    std::uint64_t bits_per_record = 0;
    for (const int f : used) {
      const E57Field& field = scan.fields[static_cast<std::size_t>(f)];
      const std::uint64_t needed = bits_needed(field, scan.record_count);
      const std::uint64_t held = streams[static_cast<std::size_t>(f)].bytes;
      if (needed / 8 > held || (needed / 8 == held && needed % 8 != 0)) {
        fail(scan, "its section holds " + std::to_string(held) + " bytes of " + field.name +
                       " but its " + std::to_string(scan.record_count) +
                       " records (recordCount) need " + std::to_string((needed + 7) / 8));
      }
      refuse_surplus(scan, field, streams[static_cast<std::size_t>(f)], needed);
      bits_per_record += field.bits;
    }
    // Fields of one value (minimum == maximum) take no bytes, so nothing in
    // the file bounds their records: all such scans together may claim no
    // more records than the file has bytes.
    if (bits_per_record == 0) {
      free_records_ += scan.record_count;
      if (free_records_ > pages.logical_size()) {
        fail(scan, "recordCount " + std::to_string(scan.record_count) +
                       " of fields that take no bits exceeds what a file of this size can hold");
      }
    }
    std::vector<E57FieldReader> readers;
    readers.reserve(scan.fields.size());
    for (std::size_t f = 0; f < scan.fields.size(); ++f)
      readers.emplace_back(scan.fields[f], streams[f]);

    E57Range colour_range[3];
    if (colours) {
      for (int c = 0; c < 3; ++c) {
        const E57Field& field = scan.fields[static_cast<std::size_t>(roles.colour[c])];
        colour_range[c] =
            checked_range(scan,
                          scan.colour_limits ? (*scan.colour_limits)[static_cast<std::size_t>(c)]
                                             : field_range(field),
                          "colour");
      }
    }
    std::optional<E57Range> intensity_range;
    if (intensities && scan.intensity_limits) {
      intensity_range = checked_range(scan, scan.intensity_limits, "intensity");
    }

    const auto count = static_cast<std::size_t>(scan.record_count);
    cloud_.reserve_positions(cloud_.positions.size() + count);
    cloud_.station_ids.reserve(cloud_.station_ids.size() + count);
    std::int64_t max_row = -1, max_column = -1;
    const auto read = [&](int f, std::uint64_t record) {
      bool ok = true;
      const double value = readers[static_cast<std::size_t>(f)].next(ok);
      if (!ok) {
        fail(scan, "record " + std::to_string(record) + ": " +
                       scan.fields[static_cast<std::size_t>(f)].name +
                       " is outside its field's minimum..maximum");
      }
      return value;
    };
    const auto grid_index = [&](int f, std::uint64_t record,
                                const std::optional<E57Range>& bounds) {
      const double value = read(f, record);
      const char* name = f == roles.row ? "rowIndex" : "columnIndex";
      if (!(value >= 0 && value <= 4e9 && value == std::floor(value))) {
        fail(scan, "record " + std::to_string(record) + ": " + name + " " + std::to_string(value) +
                       " is not a whole number in 0..4e9");
      }
      if (bounds && (value < bounds->minimum || value > bounds->maximum)) {
        fail(scan, "record " + std::to_string(record) + ": " + name + " " +
                       std::to_string(static_cast<std::int64_t>(value)) +
                       " lies outside the scan's indexBounds");
      }
      return static_cast<std::int64_t>(value);
    };
    for (std::uint64_t r = 0; r < scan.record_count; ++r) {
      double c[3];
      for (int axis = 0; axis < 3; ++axis) c[axis] = read(roles.coordinate[axis], r);
      std::array<std::uint8_t, 3> rgb{};
      for (int k = 0; k < 3 && colours; ++k) {
        const double v = read(roles.colour[k], r);
        const double unit =
            (v - colour_range[k].minimum) / (colour_range[k].maximum - colour_range[k].minimum);
        rgb[static_cast<std::size_t>(k)] =
            static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
      }
      double intensity = 0;
      if (intensities) {
        intensity = read(roles.intensity, r);
        if (intensity_range) {
          intensity = (intensity - intensity_range->minimum) /
                      (intensity_range->maximum - intensity_range->minimum);
        }
      }
      if (roles.has_grid()) {
        max_row = std::max(max_row, grid_index(roles.row, r, scan.row_bounds));
        max_column = std::max(max_column, grid_index(roles.column, r, scan.column_bounds));
      }
      if (roles.invalid_state >= 0) {
        const double state = read(roles.invalid_state, r);
        if (state != 0 && state != 1 && state != 2) {
          fail(scan, "record " + std::to_string(r) + ": invalid state " + std::to_string(state) +
                         " is none of 0 (valid), 1 (direction only), 2 (invalid)");
        }
        if (state != 0) {
          ++report_.dropped_invalid;
          continue;
        }
      }
      Eigen::Vector3d p(c[0], c[1], c[2]);
      if (roles.spherical) {
        const double range = c[0], azimuth = c[1], elevation = c[2];
        p = {range * std::cos(elevation) * std::cos(azimuth),
             range * std::cos(elevation) * std::sin(azimuth), range * std::sin(elevation)};
      }
      const Eigen::Vector3d placed = scan.rotation * p + scan.translation;
      const double xyz[3] = {placed.x(), placed.y(), placed.z()};
      const Eigen::Vector3f position = shifted_.local(xyz);
      if (!position.allFinite()) {
        ++report_.dropped_nan;
        continue;
      }
      cloud_.positions.push_back(position);
      cloud_.station_ids.push_back(index);
      if (colours) cloud_.colours.push_back(rgb);
      if (intensities) cloud_.intensities.push_back(static_cast<float>(intensity));
    }
    if (roles.has_grid()) {
      station.frame.width = grid_size(scan, scan.column_bounds, max_column, "columns");
      station.frame.height = grid_size(scan, scan.row_bounds, max_row, "rows");
    }
    cloud_.stations.push_back(std::move(station));
  }

  const std::string& path_;
  CloudReadReport& report_;
  ShiftedPositions shifted_;
  PointCloud cloud_;
  // Sections read so far: start -> (end, the scan's element).
  std::map<std::uint64_t, std::pair<std::uint64_t, std::string>> sections_;
  std::uint64_t free_records_ = 0;
};

}  // namespace

PointCloud read_e57(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report) {
  return E57CloudReader(path, options, report).run();
}

}  // namespace occlusion::detail
