#include <cmath>
#include <cstdint>
#include <ostream>
#include <sstream>
#include <string>

#include "binary_writer.hpp"
#include "cloud_formats.hpp"
#include "number_text.hpp"
#include "occlusion/io/atomic_file.hpp"

namespace occlusion::detail {
namespace {

// Points per buffered chunk: keeps memory flat for large clouds.
constexpr std::size_t kChunkPoints = 1 << 16;

std::string header(const PointCloud& cloud, const std::vector<ScalarField>& extra, bool binary) {
  std::ostringstream out;
  out << "ply\n"
      << (binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n")
      << "comment written by occlusion\n"
      << class_comment_lines(cloud.class_names, "comment ")
      << station_comment_lines(cloud.stations, cloud.shift, "comment ") << "element vertex "
      << cloud.size()
      << '\n'
      // A shifted cloud goes back to its original frame, in double.
      << (cloud.shifted() ? "property double x\nproperty double y\nproperty double z\n"
                          : "property float x\nproperty float y\nproperty float z\n");
  if (cloud.has_colours()) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  // The scalar_ prefix makes CloudCompare load them (cloud_formats.hpp).
  if (cloud.has_labels()) out << "property int " << kPlyScalarPrefix << "label\n";
  if (cloud.has_instances()) out << "property int " << kPlyScalarPrefix << "instance\n";
  // CloudCompare loads an intensity without the prefix.
  if (cloud.has_intensities()) out << "property float " << kIntensityName << '\n';
  if (cloud.has_station_ids()) out << "property int " << kPlyScalarPrefix << kStationIdName << '\n';
  for (const ScalarField& field : extra) {
    out << "property " << (field.integer ? "int " : "float ") << kPlyScalarPrefix << field.name
        << '\n';
  }
  out << "end_header\n";
  return out.str();
}

void write_binary_body(std::ostream& out, const PointCloud& cloud,
                       const std::vector<ScalarField>& extra) {
  std::string chunk;
  LittleEndianWriter buffer([&chunk](char byte) { chunk.push_back(byte); });
  const auto flush = [&] {
    out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    chunk.clear();
  };
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.shifted()) {
      const Eigen::Vector3d p = cloud.original_position(i);
      for (int axis = 0; axis < 3; ++axis) buffer.f64(p[axis]);
    } else {
      const Eigen::Vector3f& p = cloud.positions[i];
      for (int axis = 0; axis < 3; ++axis) buffer.f32(p[axis]);
    }
    if (cloud.has_colours()) {
      for (const std::uint8_t channel : cloud.colours[i]) buffer.u8(channel);
    }
    if (cloud.has_labels()) buffer.i32(cloud.labels[i]);
    if (cloud.has_instances()) buffer.i32(cloud.instances[i]);
    if (cloud.has_intensities()) buffer.f32(cloud.intensities[i]);
    if (cloud.has_station_ids()) buffer.i32(cloud.station_ids[i]);
    for (const ScalarField& field : extra) {
      if (field.integer) {
        buffer.i32(static_cast<std::int32_t>(field.values[i]));
      } else {
        buffer.f32(field.values[i]);
      }
    }
    if ((i + 1) % kChunkPoints == 0) flush();
  }
  flush();
}

void write_ascii_body(std::ostream& out, const PointCloud& cloud,
                      const std::vector<ScalarField>& extra) {
  std::string text;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      if (axis > 0) text += ' ';
      if (cloud.shifted()) {
        append_number(text, cloud.original_position(i)[axis]);
      } else {
        append_number(text, cloud.positions[i][axis]);
      }
    }
    if (cloud.has_colours()) {
      for (const std::uint8_t channel : cloud.colours[i]) {
        text += ' ';
        append_number(text, channel);
      }
    }
    if (cloud.has_labels()) {
      text += ' ';
      append_number(text, cloud.labels[i]);
    }
    if (cloud.has_instances()) {
      text += ' ';
      append_number(text, cloud.instances[i]);
    }
    if (cloud.has_intensities()) {
      text += ' ';
      append_number(text, cloud.intensities[i]);
    }
    if (cloud.has_station_ids()) {
      text += ' ';
      append_number(text, cloud.station_ids[i]);
    }
    for (const ScalarField& field : extra) {
      text += ' ';
      if (field.integer) {
        append_number(text, static_cast<long long>(field.values[i]));
      } else {
        append_number(text, field.values[i]);
      }
    }
    text += '\n';
    if ((i + 1) % kChunkPoints == 0) {
      out << text;
      text.clear();
    }
  }
  out << text;
}

}  // namespace

void write_ply(const std::string& path, const PointCloud& cloud,
               const std::vector<ScalarField>& extra, bool binary) {
  const std::string head = header(cloud, extra, binary);
  write_file_atomically(path, [&](std::ostream& out) {
    out << head;
    if (binary) {
      write_binary_body(out, cloud, extra);
    } else {
      write_ascii_body(out, cloud, extra);
    }
  });
}

}  // namespace occlusion::detail
