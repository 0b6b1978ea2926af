#include "obj_writer.hpp"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace occlusion::bench {

namespace {

void append_number(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_number(std::string& out, std::uint64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace

void write_obj(const TriangleMesh& mesh, const std::string& path, const std::string& comment) {
  std::string out;
  out.reserve(mesh.vertices.size() * 40 + mesh.faces.size() * 24);
  if (!comment.empty()) out += "# " + comment + "\n";
  for (const Eigen::Vector3d& v : mesh.vertices) {
    out += 'v';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, v[k]);
    }
    out += '\n';
  }
  std::size_t current_group = mesh.group_names.size();  // none yet
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (mesh.face_group[f] != current_group) {
      current_group = mesh.face_group[f];
      out += "g " + mesh.group_names[current_group] + "\n";
    }
    out += 'f';
    for (const std::uint32_t index : mesh.faces[f]) {
      out += ' ';
      append_number(out, static_cast<std::uint64_t>(index) + 1);
    }
    out += '\n';
  }

  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"),
                                                             &std::fclose);
  if (!file || std::fwrite(out.data(), 1, out.size(), file.get()) != out.size() ||
      std::fflush(file.get()) != 0) {
    throw std::runtime_error("write_obj: cannot write " + path + ": " + std::strerror(errno));
  }
}

}  // namespace occlusion::bench
