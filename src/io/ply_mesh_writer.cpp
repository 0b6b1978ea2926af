#include "occlusion/io/ply_mesh_writer.hpp"

#include <cstdint>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "binary_writer.hpp"
#include "cloud_formats.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/colour_ramp.hpp"

namespace occlusion {
namespace {

bool is_identifier(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  return true;
}

void check_value_name(const std::string& name) {
  if (!is_identifier(name)) {
    throw std::invalid_argument("PLY property name '" + name +
                                "' must be letters, digits and '_' only");
  }
  for (const char* taken : {"x", "y", "z", "red", "green", "blue", "vertex_indices", "group_id"}) {
    if (name == taken) {
      throw std::invalid_argument("PLY property name '" + name + "' is already used");
    }
  }
}

// A header comment ends at the end of the line, so a name must not contain one.
std::string single_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

std::string header(const TriangleMesh& mesh, const std::string& value_name) {
  std::ostringstream out;
  out << "ply\n"
      << "format binary_little_endian 1.0\n"
      << "comment written by occlusion\n"
      << "comment " << value_name << " and group_id: one value per face, repeated on the face's"
      << " own 3 vertices as scalar_" << value_name
      << " and scalar_group_id so that CloudCompare loads them as scalar fields\n"
      << "comment colour: viridis ramp of " << value_name
      << " clamped to [0,1], grey where it is NaN (no data)\n";
  for (std::size_t g = 0; g < mesh.group_names.size(); ++g) {
    out << "comment group " << g << ' ' << single_line(mesh.group_names[g]) << '\n';
  }
  out << "element vertex " << 3 * mesh.face_count() << '\n'
      << "property float x\n"
      << "property float y\n"
      << "property float z\n"
      << "property uchar red\n"
      << "property uchar green\n"
      << "property uchar blue\n"
      << "property float " << detail::kPlyScalarPrefix << value_name << '\n'
      << "property int " << detail::kPlyScalarPrefix << "group_id\n"
      << "element face " << mesh.face_count() << '\n'
      << "property list uchar int vertex_indices\n"
      << "property float " << value_name << '\n'
      << "property int group_id\n"
      << "end_header\n";
  return out.str();
}

// All vertices, then all faces, through a chunk that is written and reused
// every kChunkFaces faces, as the cloud writer does: the whole body at once
// (9 MB for 100k faces) cost as much in fresh pages as in writing.
void write_body(std::ostream& stream, const TriangleMesh& mesh,
                const std::vector<float>& face_values) {
  constexpr std::size_t kChunkFaces = 8192;
  const std::size_t faces = mesh.face_count();
  std::string chunk;
  detail::LittleEndianWriter out([&chunk](char byte) { chunk.push_back(byte); });
  const auto flush = [&] {
    stream.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    chunk.clear();
  };
  for (std::size_t f = 0; f < faces; ++f) {
    const auto rgb = colour_ramp(face_values[f]);
    for (const std::uint32_t index : mesh.faces[f]) {
      const Eigen::Vector3d& p = mesh.vertices[index];
      out.f32(static_cast<float>(p.x()));
      out.f32(static_cast<float>(p.y()));
      out.f32(static_cast<float>(p.z()));
      out.u8(rgb[0]);
      out.u8(rgb[1]);
      out.u8(rgb[2]);
      out.f32(face_values[f]);
      out.i32(static_cast<std::int32_t>(mesh.face_group[f]));
    }
    if ((f + 1) % kChunkFaces == 0) flush();
  }
  flush();
  for (std::size_t f = 0; f < faces; ++f) {
    const auto first = static_cast<std::int32_t>(3 * f);
    out.u8(3);
    out.i32(first);
    out.i32(first + 1);
    out.i32(first + 2);
    out.f32(face_values[f]);
    out.i32(static_cast<std::int32_t>(mesh.face_group[f]));
    if ((f + 1) % kChunkFaces == 0) flush();
  }
  flush();
}

}  // namespace

void write_mesh_ply(const std::string& path, const TriangleMesh& mesh,
                    const std::vector<float>& face_values, const std::string& value_name) {
  if (face_values.size() != mesh.face_count()) {
    throw std::invalid_argument("write_mesh_ply: " + std::to_string(face_values.size()) +
                                " values for " + std::to_string(mesh.face_count()) + " faces");
  }
  check_value_name(value_name);
  mesh.validate();
  // Vertex indices are PLY `int`.
  if (mesh.face_count() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) / 3) {
    throw std::invalid_argument("write_mesh_ply: too many faces for 32-bit PLY indices");
  }
  const std::string head = header(mesh, value_name);
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(head.data(), static_cast<std::streamsize>(head.size()));
    write_body(out, mesh, face_values);
  });
}

}  // namespace occlusion
