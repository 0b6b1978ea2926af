// PCL parses the header and decodes binary bodies (including the LZF of
// binary_compressed); the sizes are checked here first, because PCL reports a
// short file only as "smaller than expected" and a non-numeric ascii token not
// at all. Ascii bodies are therefore parsed here, strictly, with line numbers.

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cloud_formats.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "pcd_limits.hpp"
#include "pcd_values.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {
namespace {

using Field = pcl::PCLPointField;

enum DataType { kAscii = 0, kBinary = 1, kBinaryCompressed = 2 };

class PcdCloudReader {
 public:
  PcdCloudReader(const std::string& path, const CloudReadOptions& options, CloudReadReport& report)
      : path_(path),
        report_(report),
        shifted_(options),
        bytes_(read_file_bytes<LargeString>(path)) {}

  PointCloud run() {
    read_header();
    const std::size_t expected = points_ * blob_.point_step;
    if (data_type_ == kAscii) {
      parse_ascii_body();
    } else if (data_type_ == kBinary) {
      // Read in place: PCL would copy the body into the blob and scan it for
      // NaN, and convert() reads every value anyway.
      check_binary_size(expected);
      body_ = reinterpret_cast<const std::uint8_t*>(bytes_.data()) + data_index_;
    } else {
      check_binary_size(expected);
      const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data());
      int status = 0;
      try {
        status = reader_.readBodyBinary(data, blob_, version_, data_type_ == kBinaryCompressed,
                                        data_index_);
      } catch (const std::exception& e) {
        throw InputError(path_, 0,
                         std::string("PCL could not decode the binary data: ") + e.what());
      }
      if (status < 0) {
        throw InputError(path_, 0,
                         "PCL could not decode the binary data (its reason is printed above)");
      }
    }
    if (data_type_ != kBinary) {
      if (blob_.data.size() != expected) {
        throw InputError(path_, 0, "the data does not match the header's point count");
      }
      body_ = blob_.data.data();
    }
    map_fields();
    return convert();
  }

 private:
  // PCL's readHeader allocates WIDTH x HEIGHT x point-size bytes before it
  // looks at the data, so a corrupt count would exhaust memory: the header's
  // sizes and counts are checked here first, against the file's size and the
  // limits in pcd_limits.hpp. Whatever PCL would read as a number must be one
  // here, or PCL's own parse (stoi, unsigned wrap-around) decides the size.
  // PCL's readHeader knows a line by how its first word starts ("COUNTxyz" is
  // a COUNT line: a fuzz_pcd_ascii finding where PCL read an unchecked COUNT
  // and allocated 16 GB), and DATA's kind the same way; so does this check.
  // The keyword PCL reads `word` as; empty when it is not a header line.
  static std::string_view pcl_header_keyword(std::string_view word) {
    for (const std::string_view keyword : {"VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT",
                                           "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"}) {
      if (word.substr(0, keyword.size()) == keyword) return keyword;
    }
    return {};
  }
  static std::string_view pcl_data_kind(std::string_view word) {
    for (const std::string_view kind : {"binary_compressed", "binary"}) {
      if (word.substr(0, kind.size()) == kind) return kind;
    }
    return "ascii";
  }

  // PCL's readHeader goes on reading header lines after DATA (skipping blank
  // and comment lines) until one is not a header line, and trusts what it
  // reads there: a second SIZE line after DATA made it allocate 6 GB (a
  // fuzz_pcd_ascii finding). A PCD file's data follows its DATA line.
  void reject_header_after_data(Lines lines) const {
    std::string_view line;
    while (lines.next(line)) {
      Tokens tokens(line);
      const std::string_view word = tokens.next();
      if (word.empty() || word[0] == '#') continue;
      const std::string_view keyword = pcl_header_keyword(word);
      if (!keyword.empty()) {
        throw InputError(path_, lines.number(),
                         "a " + std::string(keyword) +
                             " header line after the DATA line; the data must follow DATA");
      }
      return;
    }
  }

  void check_declared_size() {
    std::vector<std::uint64_t> sizes;
    std::vector<std::uint64_t> counts;
    std::vector<std::uint64_t> width;
    std::vector<std::uint64_t> height;
    std::vector<std::uint64_t> points;
    std::string_view data;
    std::size_t data_end = 0;
    Lines lines(bytes_, 1, LineEnds::kLfOnly);  // counts bytes to the data
    std::string_view line;
    while (lines.next(line)) {
      data_end += line.size() + 1;
      Tokens tokens(line);
      const std::string_view keyword = pcl_header_keyword(tokens.next());
      if (keyword == "DATA") {
        data = pcl_data_kind(tokens.next());
        reject_header_after_data(lines);
        break;
      }
      std::vector<std::uint64_t>* list = keyword == "SIZE"     ? &sizes
                                         : keyword == "COUNT"  ? &counts
                                         : keyword == "WIDTH"  ? &width
                                         : keyword == "HEIGHT" ? &height
                                         : keyword == "POINTS" ? &points
                                                               : nullptr;
      if (list == nullptr) continue;
      if (!list->empty()) {
        throw InputError(path_, lines.number(), "a second " + std::string(keyword) + " line");
      }
      for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        std::int64_t value = 0;
        if (!parse_whole_number(token, value) || value < 0 ||
            static_cast<std::uint64_t>(value) > kMaxPcdHeaderNumber) {
          throw InputError(path_, lines.number(),
                           std::string(keyword) + " value " + quoted(token) +
                               " is not a whole number from 0 to " +
                               std::to_string(kMaxPcdHeaderNumber));
        }
        list->push_back(static_cast<std::uint64_t>(value));
      }
    }
    if (data.empty()) throw InputError(path_, 0, "not a PCD file (the header has no DATA line)");
    // Headers before v0.7 may give POINTS alone.
    if (sizes.empty() || width.size() > 1 || height.size() > 1 || points.size() > 1 ||
        (width.empty() && points.empty()) || (!counts.empty() && counts.size() != sizes.size())) {
      throw InputError(path_, 0,
                       "not a valid PCD header: it needs SIZE values, one WIDTH or POINTS value, "
                       "at most one HEIGHT value, and as many COUNT values as SIZE values");
    }
    std::uint64_t point_size = 0;
    std::uint64_t values_per_point = 0;
    for (std::size_t f = 0; f < sizes.size(); ++f) {
      const std::uint64_t count = counts.empty() ? 1 : counts[f];
      if (sizes[f] != 1 && sizes[f] != 2 && sizes[f] != 4 && sizes[f] != 8) {
        throw InputError(path_, 0,
                         "field " + std::to_string(f + 1) + " has SIZE " +
                             std::to_string(sizes[f]) + "; PCD fields are 1, 2, 4 or 8 bytes");
      }
      if (count == 0) {
        // PCL's own parse indexes past such a field (std::out_of_range, not a message).
        throw InputError(path_, 0,
                         "field " + std::to_string(f + 1) +
                             " has COUNT 0; a field holds at least "
                             "one value");
      }
      if (count > kMaxPcdFieldCount) {
        throw InputError(path_, 0,
                         "field " + std::to_string(f + 1) + " has COUNT " + std::to_string(count) +
                             ", more than the " + std::to_string(kMaxPcdFieldCount) +
                             " values a field may hold");
      }
      point_size += sizes[f] * count;
      values_per_point += count;
    }
    const std::uint64_t rows = height.empty() ? 1 : height[0];
    // Both below kMaxPcdHeaderNumber = 2^32, so the product fits.
    const std::uint64_t declared = width.empty() ? points[0] : width[0] * rows;
    const std::uint64_t available = bytes_.size() > data_end ? bytes_.size() - data_end : 0;
    // At most: ascii, a value and a separator (2 bytes) per value, or the
    // claim any header may make; binary, the bytes there are;
    // binary_compressed, what pcd_limits.hpp allows.
    std::uint64_t most_bytes = available;
    if (data == "ascii") {
      most_bytes = values_per_point == 0 ? 0 : (available / 2 + 1) / values_per_point * point_size;
      most_bytes = std::max(most_bytes, kPcdExpansionFloorBytes);
    } else if (data != "binary") {
      most_bytes = most_pcd_decoded_bytes(available);
    }
    const std::uint64_t most_points = point_size == 0 ? declared : most_bytes / point_size;
    const std::uint64_t claimed = points.empty() ? declared : std::max(declared, points[0]);
    if (claimed > most_points) {
      std::string why = std::to_string(available) + " bytes of " + std::string(data) +
                        " data from byte " + std::to_string(data_end) +
                        " can hold (the file ends at byte " + std::to_string(bytes_.size()) + ")";
      if (data != "ascii" && data != "binary") {
        why = "the " + std::to_string(most_bytes) + " bytes that " + std::to_string(available) +
              " bytes of " + std::string(data) + " data may expand to (" + pcd_expansion_rule() +
              ")";
      }
      throw InputError(path_, 0,
                       "truncated or corrupt: the header declares " + std::to_string(claimed) +
                           " points of " + std::to_string(point_size) + " bytes, more than " + why);
    }
    declared_bytes_ = claimed * point_size;
  }

  void read_header() {
    check_declared_size();
    // PCL's header parse sizes and zeroes the blob's data for the points it
    // reads; room in huge pages first spares a big cloud thousands of page
    // faults (a binary body is then read in place, so the blob is not used).
    blob_.data.reserve(declared_bytes_);
    advise_huge_pages(blob_.data.data(), blob_.data.capacity());
    Eigen::Vector4f origin;
    Eigen::Quaternionf orientation;
    int data_type = 0;
    unsigned int data_index = 0;
    int status = 0;
    try {
      status =
          reader_.readHeader(path_, blob_, origin, orientation, version_, data_type, data_index);
    } catch (const std::exception& e) {
      // PCL indexes its field lists with at(): FIELDS, SIZE, TYPE and COUNT
      // lines that disagree end there (fuzz_pcd_* findings), not in a message.
      throw InputError(path_, 0, std::string("not a valid PCD header: ") + e.what());
    }
    if (status < 0) {
      throw InputError(path_, 0, "not a valid PCD header (PCL's reason is printed above)");
    }
    data_type_ = data_type;
    data_index_ = data_index;
    sensor_.origin = origin.head<3>().cast<double>();
    sensor_.orientation = orientation.cast<double>();
    sensor_.width = blob_.width;
    sensor_.height = blob_.height;
    if (data_index_ > bytes_.size()) throw InputError(path_, 0, "the header is cut off");
    points_ = static_cast<std::size_t>(blob_.width) * blob_.height;
    // PCL parsed the header itself: allocate only what was checked above.
    if (static_cast<std::uint64_t>(points_) * blob_.point_step > declared_bytes_) {
      throw InputError(path_, 0,
                       "PCL reads the header as " + std::to_string(points_) + " points of " +
                           std::to_string(blob_.point_step) +
                           " bytes, more than its checked size of " +
                           std::to_string(declared_bytes_) + " bytes");
    }
    check_field_layout();
    if (data_type_ != kBinary) blob_.data.resize(points_ * blob_.point_step);

    // Class names ride in comments, which PCL skips.
    ClassNameList names;
    Lines lines(std::string_view(bytes_).substr(0, data_index_), 1, LineEnds::kLfOnly);
    std::string_view line;
    while (lines.next(line)) {
      if (line.empty() || line[0] != '#') continue;
      if (const auto comment = parse_class_comment(line.substr(1))) {
        names.add(*comment, path_, lines.number());
        continue;
      }
      try {
        if (const auto station = parse_station_comment(line.substr(1))) {
          stations_.push_back(*station);
        }
      } catch (const std::invalid_argument& e) {
        throw InputError(path_, lines.number(), e.what());
      }
    }
    class_names_ = names.finish(path_);
    data_line_ = 1 + static_cast<std::size_t>(
                         std::count(bytes_.begin(), bytes_.begin() + data_index_, '\n'));
  }

  // Every value is read and written at its field's offset with its type's
  // size, so both must be what the header declared and inside the point.
  void check_field_layout() const {
    for (const Field& field : blob_.fields) {
      if (!is_known_type(field.datatype)) {
        throw InputError(path_, 0,
                         "field '" + field.name +
                             "' has a TYPE and SIZE that are no PCD type (TYPE I or U with SIZE "
                             "1, 2, 4 or 8; F with 4 or 8)");
      }
      const std::uint64_t end =
          std::uint64_t{field.offset} + std::uint64_t{field_size(field.datatype)} * field.count;
      if (end > blob_.point_step) {
        throw InputError(path_, 0,
                         "field '" + field.name + "' ends at byte " + std::to_string(end) +
                             " of a " + std::to_string(blob_.point_step) + "-byte point");
      }
    }
  }

  void check_binary_size(std::size_t expected) const {
    const std::size_t available = bytes_.size() - data_index_;
    if (data_type_ == kBinary) {
      if (available < expected) {
        throw InputError(path_, 0,
                         "truncated: " + std::to_string(points_) + " points of " +
                             std::to_string(blob_.point_step) + " bytes need bytes " +
                             std::to_string(data_index_) + ".." +
                             std::to_string(data_index_ + expected) +
                             ", but the file ends at byte " + std::to_string(bytes_.size()));
      }
      if (available > expected) {
        throw InputError(path_, 0,
                         std::to_string(available - expected) + " bytes after the end of the " +
                             std::to_string(points_) + " points at byte " +
                             std::to_string(data_index_ + expected) +
                             " (does the header's point count match the data?)");
      }
      return;
    }
    // binary_compressed: two uint32 sizes, then the LZF block.
    if (available < 8) {
      throw InputError(path_, 0,
                       "truncated: the compressed block's sizes at byte " +
                           std::to_string(data_index_) + " are cut off (the file ends at byte " +
                           std::to_string(bytes_.size()) + ")");
    }
    std::uint32_t compressed = 0;
    std::uint32_t uncompressed = 0;
    std::memcpy(&compressed, bytes_.data() + data_index_, 4);
    std::memcpy(&uncompressed, bytes_.data() + data_index_ + 4, 4);
    if (compressed > available - 8) {
      throw InputError(path_, 0,
                       "truncated: the compressed block of " + std::to_string(compressed) +
                           " bytes starts at byte " + std::to_string(data_index_ + 8) +
                           ", but the file ends at byte " + std::to_string(bytes_.size()));
    }
    if (uncompressed > most_pcd_decoded_bytes(compressed)) {
      throw InputError(path_, 0,
                       "refused: the compressed block of " + std::to_string(compressed) +
                           " bytes would expand to " + std::to_string(uncompressed) +
                           " bytes, more than the " +
                           std::to_string(most_pcd_decoded_bytes(compressed)) + " allowed (" +
                           pcd_expansion_rule() + ")");
    }
    if (uncompressed != expected) {
      throw InputError(path_, 0,
                       "the compressed block holds " + std::to_string(uncompressed) +
                           " bytes, but " + std::to_string(points_) + " points of " +
                           std::to_string(blob_.point_step) + " bytes need " +
                           std::to_string(expected));
    }
  }

  void parse_ascii_body() {
    std::size_t values_per_point = 0;
    for (const Field& field : blob_.fields) values_per_point += field.count;
    point_lines_.reserve(points_);
    Lines lines(std::string_view(bytes_).substr(data_index_), data_line_);
    std::string_view line;
    std::size_t point = 0;
    while (lines.next(line)) {
      if (is_blank_line(line)) continue;
      if (point == points_) {
        throw InputError(
            path_, lines.number(),
            "more data lines than the " + std::to_string(points_) + " points the header declares");
      }
      Tokens tokens(line);
      std::uint8_t* record = blob_.data.data() + point * blob_.point_step;
      std::size_t read = 0;
      for (const Field& field : blob_.fields) {
        for (std::uint32_t k = 0; k < field.count; ++k, ++read) {
          const std::string_view token = tokens.next();
          if (token.empty()) {
            throw InputError(path_, lines.number(),
                             std::to_string(read) + " values; each point has " +
                                 std::to_string(values_per_point));
          }
          store_ascii(record + field.offset + k * field_size(field.datatype), field, token,
                      lines.number());
        }
      }
      if (!tokens.next().empty()) {
        throw InputError(
            path_, lines.number(),
            "more than the " + std::to_string(values_per_point) + " values each point has");
      }
      point_lines_.push_back(lines.number());
      ++point;
    }
    if (point != points_) {
      throw InputError(path_, lines.number(),
                       "the file ends after " + std::to_string(point) + " of the " +
                           std::to_string(points_) + " points the header declares");
    }
  }

  void store_ascii(std::uint8_t* at, const Field& field, std::string_view token,
                   std::size_t line) const {
    // PCL writes packed colours in ascii as the integer of their bits, since
    // many opaque colours are NaN as floats; older files wrote the float.
    if (is_packed_colour(field) && field.datatype == Field::FLOAT32) {
      std::int64_t bits = 0;
      const bool integer =
          token.find_first_of(".eEn") == std::string_view::npos && parse_whole_number(token, bits);
      if (integer && bits >= 0 && bits <= std::numeric_limits<std::uint32_t>::max()) {
        const auto narrow = static_cast<std::uint32_t>(bits);
        std::memcpy(at, &narrow, sizeof narrow);
        return;
      }
    }
    if (is_integer_type(field.datatype)) {
      std::int64_t value = 0;
      if (!parse_whole_number(token, value) || !integer_fits(field.datatype, value)) {
        throw InputError(
            path_, line,
            "field '" + field.name + "' value " + quoted(token) + " is not an integer of its type");
      }
      store_value(at, field.datatype, static_cast<double>(value));
      return;
    }
    double value = 0;
    if (!parse_double(token, value)) {
      throw InputError(path_, line,
                       "field '" + field.name + "' value " + quoted(token) + " is not a number");
    }
    store_value(at, field.datatype, value);
  }

  const Field* single(const Field& field, const char* role) const {
    if (field.count != 1) {
      throw InputError(path_, 0,
                       std::string("field '") + field.name + "' (" + role + ") has COUNT " +
                           std::to_string(field.count) + ", expected 1");
    }
    return &field;
  }

  void map_fields() {
    for (const Field& field : blob_.fields) {
      const std::string& name = field.name;
      const Field** slot = nullptr;
      if (name == "x" || name == "y" || name == "z") {
        slot = &axes_[name[0] - 'x'];
      } else if (name == "rgb" || name == "rgba") {
        if (!is_packed_colour(field)) {
          throw InputError(path_, 0, "field '" + name + "' is not a 4-byte packed colour");
        }
        slot = &packed_colour_;
      } else if (name == "r" || name == "g" || name == "b") {
        // A float channel may be 0..1 or 0..255; guessing would be a silent error.
        if (!is_integer_type(field.datatype)) {
          throw InputError(path_, 0,
                           "colour field '" + name +
                               "' is floating point; only integer colours 0..255 are read");
        }
        slot = &channels_[name == "r" ? 0 : name == "g" ? 1 : 2];
      } else if (is_label_name(name)) {
        slot = &label_;
      } else if (is_instance_name(name)) {
        slot = &instance_;
      } else if (is_intensity_name(name)) {
        slot = &intensity_;
      } else if (name == kStationIdName && !stations_.empty()) {
        // Without station comments a `scan` field is no index into them: an ordinary field.
        slot = &station_;
      }
      if (slot != nullptr) {
        if (*slot != nullptr) {
          throw InputError(
              path_, 0,
              "two fields hold the same thing ('" + (*slot)->name + "' and '" + name + "')");
        }
        *slot = single(field, name.c_str());
      } else if (field.count == 1 && name != "_") {
        extra_.push_back(&field);
      }
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (axes_[axis] == nullptr) {
        throw InputError(path_, 0, std::string("no '") + char('x' + axis) + "' field");
      }
    }
    const int channels =
        int{channels_[0] != nullptr} + int{channels_[1] != nullptr} + int{channels_[2] != nullptr};
    if (channels != 0 && channels != 3) {
      throw InputError(path_, 0, "some but not all of the fields r g b");
    }
    if (channels == 3 && packed_colour_ != nullptr) {
      throw InputError(path_, 0, "both a packed colour and r g b fields");
    }
  }

  // Where point i is, for messages: its line in ascii, its index otherwise
  // (binary_compressed stores fields apart, so a byte offset would mislead).
  [[noreturn]] void fail_at(std::size_t point, const std::string& problem) const {
    if (!point_lines_.empty()) throw InputError(path_, point_lines_[point], problem);
    throw InputError(path_, 0, "point " + std::to_string(point) + ": " + problem);
  }

  std::int32_t id_value(const Field& field, const std::uint8_t* record, bool is_label,
                        std::size_t point) const {
    double value = load_value(record + field.offset, field.datatype);
    // PCL's own label type is uint32, where "none" is 0xFFFFFFFF.
    if (field.datatype == Field::UINT32 && value == 4294967295.0) value = -1;
    if (!std::isfinite(value) || value != std::floor(value) || std::fabs(value) > 9e15) {
      fail_at(point, "field '" + field.name + "' value is not a whole number");
    }
    const auto id = static_cast<std::int64_t>(value);
    const std::string problem = id_problem(id, is_label, class_names_.size());
    if (!problem.empty()) fail_at(point, problem);
    return static_cast<std::int32_t>(id);
  }

  std::int32_t station_value(const std::uint8_t* record, std::size_t point) const {
    const double value = load_value(record + station_->offset, station_->datatype);
    if (!(value >= 0 && value < static_cast<double>(stations_.size())) ||
        value != std::floor(value)) {
      fail_at(point, "field '" + station_->name + "' value " + std::to_string(value) +
                         " names no station (the header records " +
                         std::to_string(stations_.size()) + ")");
    }
    return static_cast<std::int32_t>(value);
  }

  PointCloud convert() {
    PointCloud cloud;
    cloud.class_names = class_names_;
    cloud.sensor = sensor_;
    const bool colours = packed_colour_ != nullptr || channels_[0] != nullptr;
    cloud.reserve_positions(points_);
    if (colours) cloud.colours.reserve(points_);
    if (label_ != nullptr) cloud.labels.reserve(points_);
    if (instance_ != nullptr) cloud.instances.reserve(points_);
    if (intensity_ != nullptr) cloud.intensities.reserve(points_);
    if (station_ != nullptr) cloud.station_ids.reserve(points_);
    // An organised PCD's records are its pixels, row by row.
    const bool organised =
        sensor_.organised() && points_ <= std::numeric_limits<std::uint32_t>::max();
    if (organised) cloud.pixels.reserve(points_);
    cloud.stations = stations_;
    std::vector<ScalarField> extra;
    for (const Field* field : extra_) {
      extra.push_back({field->name, {}, is_integer_type(field->datatype)});
      extra.back().values.reserve(points_);
    }

    for (std::size_t i = 0; i < points_; ++i) {
      const std::uint8_t* record = body_ + i * blob_.point_step;
      double xyz[3];
      for (int axis = 0; axis < 3; ++axis) {
        xyz[axis] = load_value(record + axes_[axis]->offset, axes_[axis]->datatype);
      }
      const Eigen::Vector3f position = shifted_.local(xyz);
      if (!position.allFinite()) {
        ++report_.dropped_nan;
        continue;
      }
      cloud.positions.push_back(position);
      if (organised) cloud.pixels.push_back(static_cast<std::uint32_t>(i));
      if (packed_colour_ != nullptr) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, record + packed_colour_->offset, sizeof bits);
        cloud.colours.push_back({static_cast<std::uint8_t>(bits >> 16),
                                 static_cast<std::uint8_t>(bits >> 8),
                                 static_cast<std::uint8_t>(bits)});
      } else if (colours) {
        std::array<std::uint8_t, 3> rgb{};
        for (int c = 0; c < 3; ++c) {
          const double value = load_value(record + channels_[c]->offset, channels_[c]->datatype);
          if (!(value >= 0 && value <= 255)) {
            fail_at(i, "colour field '" + channels_[c]->name + "' is outside 0..255");
          }
          rgb[c] = static_cast<std::uint8_t>(value);
        }
        cloud.colours.push_back(rgb);
      }
      if (label_ != nullptr) cloud.labels.push_back(id_value(*label_, record, true, i));
      if (instance_ != nullptr) cloud.instances.push_back(id_value(*instance_, record, false, i));
      if (intensity_ != nullptr) {
        cloud.intensities.push_back(
            static_cast<float>(load_value(record + intensity_->offset, intensity_->datatype)));
      }
      if (station_ != nullptr) cloud.station_ids.push_back(station_value(record, i));
      for (std::size_t f = 0; f < extra_.size(); ++f) {
        extra[f].values.push_back(
            static_cast<float>(load_value(record + extra_[f]->offset, extra_[f]->datatype)));
      }
    }
    for (ScalarField& field : extra) report_.extra_fields.push_back(std::move(field));
    cloud.shift = shifted_.checked_shift(path_);
    cloud.sensor.origin = cloud.to_local(cloud.sensor.origin);
    for (Station& station : cloud.stations) {
      station.frame.origin = cloud.to_local(station.frame.origin);
    }
    return cloud;
  }

  const std::string& path_;
  CloudReadReport& report_;
  ShiftedPositions shifted_;
  LargeString bytes_;
  pcl::PCDReader reader_;
  pcl::PCLPointCloud2 blob_;            // its data holds decoded ascii and compressed bodies
  const std::uint8_t* body_ = nullptr;  // the points, point_step bytes each
  int version_ = 0;
  int data_type_ = 0;
  unsigned int data_index_ = 0;
  SensorFrame sensor_;
  std::size_t data_line_ = 1;
  std::size_t points_ = 0;
  std::uint64_t declared_bytes_ = 0;  // the point data the header may claim
  std::vector<std::string> class_names_;
  std::vector<Station> stations_;         // from the header's comments, in the file's frame
  std::vector<std::size_t> point_lines_;  // ascii only

  const Field* axes_[3] = {nullptr, nullptr, nullptr};
  const Field* packed_colour_ = nullptr;
  const Field* channels_[3] = {nullptr, nullptr, nullptr};
  const Field* label_ = nullptr;
  const Field* instance_ = nullptr;
  const Field* intensity_ = nullptr;
  const Field* station_ = nullptr;
  std::vector<const Field*> extra_;
};

}  // namespace

PointCloud read_pcd(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report) {
  return PcdCloudReader(path, options, report).run();
}

}  // namespace occlusion::detail
