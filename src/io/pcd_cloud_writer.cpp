// PCL writes the header and, for binary_compressed, the LZF body; the ascii body
// is written here so that floats keep every bit (PCL prints 8 significant
// digits, one short of a float's 9). A shifted cloud (PointCloud::shift) gets
// x y z as double in its original frame.

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <sstream>

#include "cloud_formats.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::detail {
namespace {

using Field = pcl::PCLPointField;

void add_field(pcl::PCLPointCloud2& blob, const std::string& name, std::uint8_t datatype) {
  Field field;
  field.name = name;
  field.offset = blob.point_step;
  field.datatype = datatype;
  field.count = 1;
  blob.fields.push_back(field);
  blob.point_step += datatype == Field::FLOAT64 ? 8 : 4;
}

template <class T>
void put(pcl::PCLPointCloud2& blob, std::size_t point, std::size_t field, T value) {
  static_assert(sizeof(T) == 4 || sizeof(T) == 8, "fields are written 4 or 8 bytes wide");
  std::memcpy(blob.data.data() + point * blob.point_step + blob.fields[field].offset, &value,
              sizeof value);
}

pcl::PCLPointCloud2 to_blob(const PointCloud& cloud, const std::vector<ScalarField>& extra) {
  pcl::PCLPointCloud2 blob;
  const bool shifted = cloud.shifted();
  for (const char* axis : {"x", "y", "z"}) {
    add_field(blob, axis, shifted ? Field::FLOAT64 : Field::FLOAT32);
  }
  if (cloud.has_colours()) add_field(blob, "rgb", Field::FLOAT32);
  // uint32 as in PCL's PointXYZL and PointXYZRGBL, which load only an exact
  // type match; -1 (none) becomes 0xFFFFFFFF, which the reader maps back.
  if (cloud.has_labels()) add_field(blob, "label", Field::UINT32);
  if (cloud.has_instances()) add_field(blob, "instance", Field::INT32);
  if (cloud.has_intensities()) add_field(blob, std::string(kIntensityName), Field::FLOAT32);
  if (cloud.has_station_ids()) add_field(blob, std::string(kStationIdName), Field::INT32);
  for (const ScalarField& field : extra) {
    add_field(blob, field.name, field.integer ? Field::INT32 : Field::FLOAT32);
  }
  blob.width = static_cast<std::uint32_t>(cloud.size());
  blob.height = 1;
  blob.is_dense = true;
  blob.row_step = blob.point_step * blob.width;
  blob.data.resize(static_cast<std::size_t>(blob.row_step));

  for (std::size_t i = 0; i < cloud.size(); ++i) {
    std::size_t f = 0;
    if (shifted) {
      const Eigen::Vector3d original = cloud.original_position(i);
      for (int axis = 0; axis < 3; ++axis) put(blob, i, f++, original[axis]);
    } else {
      for (int axis = 0; axis < 3; ++axis) put(blob, i, f++, cloud.positions[i][axis]);
    }
    if (cloud.has_colours()) {
      // PCL's packing, alpha opaque as PCL's own point types write it.
      const auto& rgb = cloud.colours[i];
      const std::uint32_t packed = 0xFF000000u | std::uint32_t{rgb[0]} << 16 |
                                   std::uint32_t{rgb[1]} << 8 | std::uint32_t{rgb[2]};
      put(blob, i, f++, packed);
    }
    if (cloud.has_labels()) put(blob, i, f++, static_cast<std::uint32_t>(cloud.labels[i]));
    if (cloud.has_instances()) put(blob, i, f++, cloud.instances[i]);
    if (cloud.has_intensities()) put(blob, i, f++, cloud.intensities[i]);
    if (cloud.has_station_ids()) put(blob, i, f++, cloud.station_ids[i]);
    for (const ScalarField& field : extra) {
      if (field.integer) {
        put(blob, i, f++, static_cast<std::int32_t>(field.values[i]));
      } else {
        put(blob, i, f++, field.values[i]);
      }
    }
  }
  return blob;
}

// The shortest text that reads back as the same value; the packed colour as
// the integer of its bits, as PCL writes and reads it in ascii.
std::string ascii_body(const pcl::PCLPointCloud2& blob) {
  std::string text;
  char digits[32];
  for (std::size_t i = 0; i < blob.width; ++i) {
    const std::uint8_t* record = blob.data.data() + i * blob.point_step;
    for (std::size_t f = 0; f < blob.fields.size(); ++f) {
      const Field& field = blob.fields[f];
      if (f > 0) text += ' ';
      char* end = digits;
      if (field.datatype == Field::INT32) {
        std::int32_t value;
        std::memcpy(&value, record + field.offset, sizeof value);
        end = std::to_chars(digits, digits + sizeof digits, value).ptr;
      } else if (field.datatype == Field::UINT32 || field.name == "rgb") {
        std::uint32_t value;
        std::memcpy(&value, record + field.offset, sizeof value);
        end = std::to_chars(digits, digits + sizeof digits, value).ptr;
      } else if (field.datatype == Field::FLOAT64) {
        double value;
        std::memcpy(&value, record + field.offset, sizeof value);
        end = std::to_chars(digits, digits + sizeof digits, value).ptr;
      } else {
        float value;
        std::memcpy(&value, record + field.offset, sizeof value);
        end = std::to_chars(digits, digits + sizeof digits, value).ptr;
      }
      text.append(digits, end);
    }
    text += '\n';
  }
  return text;
}

// Class-name and station comments go after PCL's first line (its own "#
// .PCD v0.7" comment): readers skip comment lines anywhere before DATA.
std::string with_comments(const std::string& file, const PointCloud& cloud) {
  if (cloud.class_names.empty() && cloud.stations.empty()) return file;
  const std::size_t first_line_end = file.find('\n');
  const std::size_t insert_at =
      (file.rfind('#', 0) == 0 && first_line_end != std::string::npos) ? first_line_end + 1 : 0;
  std::string out = file.substr(0, insert_at);
  out += class_comment_lines(cloud.class_names, "# ");
  out += station_comment_lines(cloud.stations, cloud.shift, "# ");
  out.append(file, insert_at, std::string::npos);
  return out;
}

}  // namespace

void write_pcd(const std::string& path, const PointCloud& cloud,
               const std::vector<ScalarField>& extra, CloudFormat format) {
  const pcl::PCLPointCloud2 blob = to_blob(cloud, extra);
  const Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  const Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  pcl::PCDWriter writer;
  std::string file;
  if (format == CloudFormat::kPcdBinaryCompressed) {
    std::ostringstream stream;
    if (writer.writeBinaryCompressed(stream, blob, origin, orientation) != 0) {
      throw OutputError(path, "PCL could not write the binary_compressed PCD");
    }
    file = stream.str();
  } else if (format == CloudFormat::kPcdBinary) {
    file = writer.generateHeaderBinary(blob, origin, orientation) + "DATA binary\n";
    file.append(reinterpret_cast<const char*>(blob.data.data()), blob.data.size());
  } else {
    // PCL's generated headers stop before the DATA line, which its writers add.
    file =
        writer.generateHeaderASCII(blob, origin, orientation) + "DATA ascii\n" + ascii_body(blob);
  }
  file = with_comments(file, cloud);
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(file.data(), static_cast<std::streamsize>(file.size()));
  });
}

}  // namespace occlusion::detail
